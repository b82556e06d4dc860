// b2analytic benchmark: run time against error per 3D shape pair, for each of our 3D contact
// methods and for what a 3D engine user would do instead (Bullet's GJK/EPA on convex hulls of
// surface points), measured side by side in one process.
#include "BenchCommon.h"
#include "PairsPlot.h"
#include "common/CommandLine.h"

#include "b2analytic/3d/Contact3.h"
#include "b2analytic/3d/SuperellipsoidShape.h"
#include "Reference3.h"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::bench;
using namespace b2a::demo;
namespace r3 = b2a::test::ref3;
using r3::LD;

namespace
{
const char* kHelp = R"(b2a_bench_pairs3d: time against error per 3D shape pair.

For each pair family (spheres, ellipsoids of aspect 3 to 100, superellipsoids with integer and
non-integer exponents, the paper's Figure 17 pair, a superellipsoid of aspect 100) it poses
pairs from a fixed seed: separated (gaps of 2% to 50% of the size), near-tangent (gap below
1e-12 of the size) and overlapping (1% to 25% of the size), and from each a sequence of small
motions for warm starts. Every method is timed over the same poses (median of repeats,
nanoseconds of thread CPU time per query) in alternation with Bullet's GJK/EPA on 64-point
hulls, for its ratio to them, and its answers are compared with long-double references (the
common level's equations solved by Newton in long double; Perram-Wertheim by bisection for
ellipsoids; the contact's points by bisection along the normal):
  newton_cold, newton_warm  Newton on the common level (warm: carried along the motions)
  auto, auto_warm           the automatic path (the 3D dispatch table)
  grid_<N>                  the paper's grid method with N samples, not refined
  grid_refined              the grid method (256 samples) refined between samples
  bullet_gjk_epa<N>         Bullet 3 (double precision) btGjkPairDetector with
                            btGjkEpaPenetrationDepthSolver on btConvexHullShapes of N surface
                            points (N = 32 to 512, margin 0: the inscribed polytope itself)
Errors, relative to the pair's size (the mean bounding radius): contact points, normal angle
(radians) and separation. Bullet's answers (closest points or EPA's penetration) are compared
over the near-tangent poses, where the Euclidean gap and the level contact's gap along its
normal agree (away from tangency they differ at second order); a contact it misses where the
shapes overlap, or reports where they are apart beyond its hull's error, is a failure.

Writes DIR/pairs3d.csv (the columns of b2a_bench_pairs' pairs.csv, the ratio against
bullet_gjk_epa64), DIR/pairs3d.md and DIR/pairs3d_<family>.svg.
)";

struct Family
{
	std::string name;
	std::shared_ptr<SuperellipsoidShape> a, b;
};

std::vector<Family> Families()
{
	auto se = [](double a, double b, double c, double n1, double n2, double n3) { return MakeSuperellipsoid(a, b, c, n1, n2, n3); };
	return {
		{"sphere", MakeSphere(1.0), MakeSphere(0.7)},
		{"ellipsoid_a3", MakeEllipsoid(1.0, 0.6, 1.0 / 3), MakeEllipsoid(0.8, 0.5, 0.8 / 3)},
		{"ellipsoid_a10", MakeEllipsoid(1.0, 0.4, 0.1), MakeEllipsoid(0.8, 0.3, 0.08)},
		{"ellipsoid_a100", MakeEllipsoid(5.0, 0.5, 0.05), MakeEllipsoid(4.0, 0.4, 0.04)},
		{"superellipsoid_n4", se(1.0, 0.8, 0.6, 4, 4, 4), se(0.8, 0.6, 0.5, 4, 4, 4)},
		{"superellipsoid_n8", se(1.0, 0.8, 0.6, 8, 8, 8), se(0.8, 0.6, 0.5, 8, 8, 8)},
		{"superellipsoid_fig17", se(4, 4, 4, 6, 6, 12), se(2, 3, 2, 8, 8, 8)},
		{"superellipsoid_n2.5_3.7_5.3", se(1.0, 0.8, 0.6, 2.5, 3.7, 5.3), se(0.8, 0.6, 0.5, 5.3, 2.5, 3.7)},
		{"superellipsoid_a100", se(5.0, 0.5, 0.05, 4, 4, 4), se(4.0, 0.4, 0.04, 4, 6, 4)},
	};
}

double PairSize(const Family& f) { return 0.5 * (f.a->BoundingRadius() + f.b->BoundingRadius()); }

enum class PoseClass { separated, nearTangent, overlapping };

struct PairPose
{
	Pose3 pa, pb;
	PoseClass cls;
	int sequence = -1; // -1: a base pose; else the index of its base pose (a warm-start motion)
	btTransform xa, xb; // the poses as Bullet holds them, made with the poses, not timed
};

btTransform ToBullet(const Pose3& p)
{
	return btTransform(btQuaternion(p.q.x, p.q.y, p.q.z, p.q.w), btVector3(p.p.x, p.p.y, p.p.z));
}

Quat RandomRotation(std::mt19937_64& rng)
{
	std::normal_distribution<double> n(0.0, 1.0);
	return Normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
}

Vec3 RandomUnit(std::mt19937_64& rng)
{
	std::normal_distribution<double> n(0.0, 1.0);
	return Normalize(Vec3(n(rng), n(rng), n(rng)));
}

// B along the direction u from A at the centre distance where the automatic contact's
// separation equals `gap` (bisection; the separation grows with the distance), or false where
// even centres 1e-6 of the reach apart overlap less, or the pose's common level is below 1e-9:
// the caller draws another. The library only places the poses: every error is measured against the
// long-double reference.
bool PlaceB(const Family& f, const Pose3& pa, Quat qb, Vec3 u, double gap, Pose3& pb)
{
	const double far = 1.05 * (f.a->BoundingRadius() + f.b->BoundingRadius()) + std::fabs(gap);
	auto sep = [&](double t) { return ComputeContact(*f.a, pa, *f.b, Pose3(pa.p + t * u, qb)).separation - gap; };
	double lo = 1e-6 * far, hi = far;
	if (sep(lo) > 0.0)
		return false;
	for (int i = 0; i < 100 && hi - lo > 1e-15 * far; ++i)
	{
		const double mid = 0.5 * (lo + hi);
		(sep(mid) < 0.0 ? lo : hi) = mid;
	}
	pb = Pose3(pa.p + 0.5 * (lo + hi) * u, qb);
	// Thin plates crossing reach a deep overlap only with their centres a hair apart, where the
	// common level is below 1e-9 and its point is not determined: drawn again (b2a_stress3d
	// counts such poses apart).
	return ComputeContact(*f.a, pa, *f.b, pb).level >= 1e-9;
}

std::vector<PairPose> MakePoses(const Family& f, int perClass, int motions, std::mt19937_64& rng)
{
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	const double size = PairSize(f);
	std::vector<PairPose> poses;
	for (PoseClass cls : {PoseClass::separated, PoseClass::nearTangent, PoseClass::overlapping})
		for (int k = 0; k < perClass; ++k)
		{
			Pose3 pa, pb;
			for (bool placed = false; !placed;)
			{
				pa = Pose3(Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5), RandomRotation(rng));
				const Vec3 u = RandomUnit(rng);
				const Quat qb = RandomRotation(rng);
				double gap = 0.0;
				if (cls == PoseClass::separated)
					gap = size * (0.02 + 0.48 * unit(rng));
				else if (cls == PoseClass::overlapping)
					gap = -size * (0.01 + 0.24 * unit(rng));
				placed = PlaceB(f, pa, qb, u, gap, pb);
			}
			const int base = int(poses.size());
			poses.push_back({pa, pb, cls, -1, ToBullet(pa), ToBullet(pb)});
			// Small motions of B relative to A, as between time steps: 0.1% of the size and
			// 1 mrad per step.
			Pose3 moved = pb;
			for (int s = 0; s < motions; ++s)
			{
				const Vec3 d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
				moved = Pose3(moved.p + 2e-3 * size * d, Normalize(RotationVector(1e-3 * RandomUnit(rng)) * moved.q));
				poses.push_back({pa, moved, cls, base, ToBullet(pa), ToBullet(moved)});
			}
		}
	return poses;
}

// ------------------------------------------------------------------------------------------
// The long-double reference contact
// ------------------------------------------------------------------------------------------

struct RefContact
{
	r3::V3 pointA, pointB, normal;
	LD separation = 0.0L;
	bool ok = false;
};

// The largest t with f(X + t·n) = 1 along a convex shape's line (g = f^{1/p} − 1 is convex in t):
// its minimum by golden section, then bisection between it and a point beyond the shape; the
// radial point towards X where the line misses.
r3::V3 LineExtremeL(const r3::Shape& s, const r3::Pose& p, r3::V3 X, r3::V3 n, LD reach)
{
	auto g = [&](LD t) { return s.Level(p.ToBody(X + t * n)) - 1.0L; };
	LD lo = -reach, hi = reach;
	const LD phi = 0.381966011250105151795413165634361883L;
	LD x1 = lo + phi * (hi - lo), x2 = hi - phi * (hi - lo), f1 = g(x1), f2 = g(x2);
	for (int k = 0; k < 200 && hi - lo > 1e-18L * reach; ++k)
	{
		if (f1 < f2) { hi = x2; x2 = x1; f2 = f1; x1 = lo + phi * (hi - lo); f1 = g(x1); }
		else { lo = x1; x1 = x2; f1 = f2; x2 = hi - phi * (hi - lo); f2 = g(x2); }
	}
	LD inside = 0.5L * (lo + hi), outside = reach;
	if (!(g(inside) <= 0.0L))
		return p.ToWorld(r3::OnLevel(s, p.ToBody(X) - r3::V3{}, 1.0L)); // the line misses: radial point
	for (int k = 0; k < 200 && outside - inside > 1e-21L * reach; ++k)
	{
		const LD mid = 0.5L * (inside + outside);
		(g(mid) <= 0.0L ? inside : outside) = mid;
	}
	return X + (0.5L * (inside + outside)) * n;
}

RefContact Reference(const Family& f, const PairPose& pose)
{
	RefContact ref;
	const r3::Shape A(*f.a), B(*f.b);
	const r3::Pose pa(pose.pa), pb(pose.pb);
	// The common level's point: Perram–Wertheim for ellipsoids, else the long-double Newton
	// polish of the equations from the library's answer (unique for convex shapes).
	r3::SurfaceMinimum m;
	const bool quadrics = f.a->Exponent(0) == 2 && f.a->Exponent(1) == 2 && f.a->Exponent(2) == 2 && f.b->Exponent(0) == 2 &&
	                      f.b->Exponent(1) == 2 && f.b->Exponent(2) == 2;
	if (quadrics)
		m = r3::PerramWertheim(A, pa, B, pb);
	else
	{
		const LevelResult3 start = SolveCommonLevel(*f.a, pose.pa, *f.b, pose.pb);
		if (!start.Ok())
			return ref;
		const r3::V3 X = r3::From(start.point);
		const r3::V3 ga = pa.Rotate(A.Gradient(pa.ToBody(X))), gb = pb.Rotate(B.Gradient(pb.ToBody(X)));
		m = r3::Polish(A, pa, B, pb, X, -r3::Dot(ga, gb) / r3::Dot(gb, gb));
	}
	const r3::V3 X = m.point;
	const r3::V3 na = r3::Unit(pa.Rotate(A.Gradient(pa.ToBody(X)))), nb = r3::Unit(pb.Rotate(B.Gradient(pb.ToBody(X))));
	ref.normal = r3::Unit(na - nb);
	const LD reach = 4.0L * (f.a->BoundingRadius() + f.b->BoundingRadius()) + r3::Len(X - pa.p) + r3::Len(X - pb.p);
	ref.pointA = LineExtremeL(A, pa, X, ref.normal, reach);
	ref.pointB = LineExtremeL(B, pb, X, -1.0L * ref.normal, reach);
	ref.separation = r3::Dot(ref.pointB - ref.pointA, ref.normal);
	ref.ok = true;
	return ref;
}

// ------------------------------------------------------------------------------------------
// Methods
// ------------------------------------------------------------------------------------------

struct Answer
{
	bool ok = false;
	Vec3 pointA, pointB, normal;
	double separation = 0.0;
	bool bullet = false; // Euclidean closest points / EPA: compared near tangency only
};

struct Method
{
	std::string name;
	bool warm = false;
	std::function<void(const Family&, const std::vector<PairPose>&, const std::vector<int>&, std::vector<Answer>*)> run;
};

Answer FromContact(const ContactResult3& c)
{
	Answer a;
	a.ok = c.Ok() && std::isfinite(c.separation) && IsFinite(c.pointA) && IsFinite(c.pointB) && IsFinite(c.normal);
	a.pointA = c.pointA;
	a.pointB = c.pointB;
	a.normal = c.normal;
	a.separation = c.separation;
	return a;
}

// N points on the shape's surface spread over its own directions (a Fibonacci lattice of the
// sphere, scaled by the semi-axes and taken to the surface along the ray): what a user would
// hand to a convex hull shape.
std::shared_ptr<btConvexHullShape> Hull(const SuperellipsoidShape& s, int count)
{
	auto hull = std::make_shared<btConvexHullShape>();
	const double golden = kPi * (3.0 - std::sqrt(5.0));
	for (int k = 0; k < count; ++k)
	{
		const double z = 1.0 - (2.0 * k + 1.0) / count, r = std::sqrt(std::max(0.0, 1.0 - z * z));
		const Vec3 d(s.A() * r * std::cos(golden * k), s.B() * r * std::sin(golden * k), s.C() * z);
		const Vec3 p = s.PointOnRay(d, 1.0);
		hull->addPoint(btVector3(p.x, p.y, p.z), false);
	}
	hull->recalcLocalAabb();
	hull->setMargin(0.0);
	return hull;
}

std::vector<Method> Methods(const Family& f)
{
	std::vector<Method> methods;
	auto each = [](const std::vector<PairPose>& poses, const std::vector<int>& which, auto&& body) {
		for (size_t i = 0; i < which.size(); ++i)
			body(poses[which[i]], i);
	};
	auto contactMethod = [&](std::string name, MethodChoice choice, SolverOptions options) {
		methods.push_back({name, false,
			[choice, options, each](const Family& fam, const std::vector<PairPose>& poses, const std::vector<int>& which,
			                        std::vector<Answer>* out) {
				each(poses, which, [&](const PairPose& p, size_t i) {
					const ContactResult3 c = ComputeContact(*fam.a, p.pa, *fam.b, p.pb, choice, options);
					KeepAlive(c);
					if (out)
						(*out)[i] = FromContact(c);
				});
			}});
	};
	// A warm start carried along each motion sequence from its base pose's solution (computed
	// once, outside the timing).
	auto warmMethod = [&](std::string name, MethodChoice choice) {
		auto bases = std::make_shared<std::map<int, WarmStart3>>();
		methods.push_back({name, true,
			[choice, bases, each](const Family& fam, const std::vector<PairPose>& poses, const std::vector<int>& which,
			                      std::vector<Answer>* out) {
				WarmStart3 warm;
				int current = -2;
				each(poses, which, [&](const PairPose& p, size_t i) {
					if (p.sequence != current)
					{
						current = p.sequence;
						auto it = bases->find(current);
						if (it == bases->end())
						{
							WarmStart3 w;
							ComputeContact(*fam.a, poses[current].pa, *fam.b, poses[current].pb, choice, {}, &w);
							it = bases->emplace(current, w).first;
						}
						warm = it->second;
					}
					const ContactResult3 c = ComputeContact(*fam.a, p.pa, *fam.b, p.pb, choice, {}, &warm);
					KeepAlive(c);
					if (out)
						(*out)[i] = FromContact(c);
				});
			}});
	};
	contactMethod("newton_cold", MethodChoice::newton, {});
	warmMethod("newton_warm", MethodChoice::newton);
	contactMethod("auto", MethodChoice::automatic, {});
	warmMethod("auto_warm", MethodChoice::automatic);
	for (int samples : {256, 1024, 4096})
	{
		SolverOptions o;
		o.gridSamples = samples;
		o.gridRefine = false;
		contactMethod("grid_" + std::to_string(samples), MethodChoice::grid, o);
	}
	contactMethod("grid_refined", MethodChoice::grid, {});
	for (int count : {32, 64, 128, 256, 512})
	{
		auto ha = Hull(*f.a, count), hb = Hull(*f.b, count);
		methods.push_back({"bullet_gjk_epa" + std::to_string(count), false,
			[ha, hb, each](const Family&, const std::vector<PairPose>& poses, const std::vector<int>& which,
			               std::vector<Answer>* out) {
				btVoronoiSimplexSolver simplex;
				btGjkEpaPenetrationDepthSolver epa;
				btGjkPairDetector detector(ha.get(), hb.get(), &simplex, &epa);
				btDiscreteCollisionDetectorInterface::ClosestPointInput input;
				each(poses, which, [&](const PairPose& p, size_t i) {
					input.m_transformA = p.xa;
					input.m_transformB = p.xb;
					btPointCollector result;
					detector.getClosestPoints(input, result, nullptr);
					KeepAlive(result);
					if (out)
					{
						Answer& a = (*out)[i];
						a.bullet = true;
						a.ok = result.m_hasResult && std::isfinite(result.m_distance);
						if (a.ok)
						{
							// Bullet's normal points from B to A, its point lies on B.
							const Vec3 n(-result.m_normalOnBInWorld.x(), -result.m_normalOnBInWorld.y(), -result.m_normalOnBInWorld.z());
							const Vec3 onB(result.m_pointInWorld.x(), result.m_pointInWorld.y(), result.m_pointInWorld.z());
							a.normal = n;
							a.pointB = onB;
							a.pointA = onB - result.m_distance * n;
							a.separation = result.m_distance;
						}
					}
				});
			}});
	}
	return methods;
}

// ------------------------------------------------------------------------------------------
// Errors
// ------------------------------------------------------------------------------------------

struct Errors
{
	double point = 0.0, normal = 0.0, separation = 0.0;
	int failures = 0, compared = 0;
};

double AngleBetween(Vec3 a, r3::V3 b)
{
	const r3::V3 al = r3::From(a);
	return double(std::atan2(r3::Len(r3::Cross(al, b)), r3::Dot(al, b)));
}

void Accumulate(const Answer& ans, const RefContact& ref, PoseClass cls, double size, double hullError, Errors& e)
{
	if (!ans.ok || !ref.ok)
	{
		++e.failures;
		return;
	}
	if (ans.bullet)
	{
		// A verdict beyond the hull's own error is wrong: a missed overlap, or a contact reported
		// between shapes apart.
		const bool refTouching = ref.separation <= 0.0L;
		if ((ans.separation <= 0.0) != refTouching && std::fabs(double(ref.separation)) > hullError)
		{
			++e.failures;
			return;
		}
		if (cls != PoseClass::nearTangent)
			return;
	}
	else if ((ans.separation <= 0.0) != (ref.separation <= 0.0L) && std::fabs(double(ref.separation)) > 1e-9 * size)
	{
		++e.failures; // a wrong verdict (the plain grid's, beyond rounding)
		return;
	}
	e.point = std::fmax(e.point, double(std::fmax(r3::Dist(ans.pointA, ref.pointA), r3::Dist(ans.pointB, ref.pointB))) / size);
	e.normal = std::fmax(e.normal, AngleBetween(ans.normal, ref.normal));
	e.separation = std::fmax(e.separation, double(std::fabs(LD(ans.separation) - ref.separation)) / size);
	++e.compared;
}

struct Row
{
	std::string family, method;
	double ns = 0.0, ratio = std::nan("");
	Errors errors;
	int queries = 0;
};

// The largest distance from the hull of `count` surface points to the surface, measured on
// dense samples: how far Bullet's answers may be off by construction.
double HullError(const SuperellipsoidShape& s, int count)
{
	const auto hull = Hull(s, count);
	double worst = 0.0;
	for (const Vec3& p : s.Samples(8000).point)
	{
		const Vec3 u = Normalize(p);
		const btVector3 support = hull->localGetSupportingVertex(btVector3(u.x, u.y, u.z));
		worst = std::fmax(worst, s.SupportValue(u) - (support.x() * u.x + support.y() * u.y + support.z() * u.z));
	}
	return worst;
}
} // namespace

int main(int argc, char** argv)
{
	std::vector<Family> families = Families();
	std::vector<std::string> allNames, familyNames;
	for (const Family& f : families)
		allNames.push_back(f.name);
	int perClass = 0, repeats = 0;
	CommandLine cli("b2a_bench_pairs3d", kHelp);
	cli.Add("--poses", perClass, 20, 4, "N", "poses per class and family (default 20, quick 4)", WholeNumber(1, 100000));
	cli.Add("--repeats", repeats, 9, 3, "N", "repeats of each timing, of which the median is reported (default 9, quick 3)", WholeNumber(1, 1000));
	cli.Add("--families", familyNames, "NAME,NAME", "only these pair families (default all)", OneOf(allNames));
	const DemoOptions opt = cli.Parse(argc, argv);
	const int motions = opt.quick ? 4 : 8;
	const MachineInfo machine = GetMachineInfo();
	Progress progress("b2a_bench_pairs3d");
	SelectFamilies(families, familyNames);
	std::vector<Row> rows;
	for (size_t fi = 0; fi < families.size(); ++fi)
	{
		const Family& f = families[fi];
		const double size = PairSize(f);
		std::mt19937_64 rng = FamilyRng(opt.seed, f.name);
		progress.Report(double(fi) / families.size(), f.name + ": poses and references");
		const std::vector<PairPose> poses = MakePoses(f, perClass, motions, rng);
		std::vector<int> base, moved;
		for (size_t i = 0; i < poses.size(); ++i)
			(poses[i].sequence < 0 ? base : moved).push_back(int(i));
		std::vector<RefContact> refs(poses.size());
		for (size_t i = 0; i < poses.size(); ++i)
			refs[i] = Reference(f, poses[i]);

		progress.Report((fi + 0.5) / families.size(), f.name + ": timing");
		const std::vector<Method> methods = Methods(f);
		const Method* baseline = nullptr;
		for (const Method& m : methods)
			if (m.name == "bullet_gjk_epa64")
				baseline = &m;
		for (const Method& m : methods)
		{
			const std::vector<int>& which = m.warm ? moved : base;
			std::vector<Answer> answers(which.size());
			m.run(f, poses, which, &answers);
			Row row;
			row.family = f.name;
			row.method = m.name;
			row.queries = int(which.size());
			double hullError = 0.0;
			if (m.name.rfind("bullet_gjk_epa", 0) == 0)
			{
				const int count = std::stoi(m.name.substr(14));
				hullError = HullError(*f.a, count) + HullError(*f.b, count);
			}
			for (size_t i = 0; i < which.size(); ++i)
				Accumulate(answers[i], refs[which[i]], poses[which[i]].cls, size, hullError, row.errors);
			// The plain grid rows take milliseconds a query at aspect 100: a third of the repeats.
			const bool slow = m.name.rfind("grid_", 0) == 0;
			const PairedTiming t = TimeAgainstBaseline([&] { m.run(f, poses, which, nullptr); },
			                                           [&] { baseline->run(f, poses, which, nullptr); }, &m == baseline,
			                                           int(which.size()), slow ? std::max(1, repeats / 3) : repeats);
			row.ns = t.ns;
			row.ratio = t.ratio;
			rows.push_back(row);
		}
		std::fprintf(stderr, "b2a_bench_pairs3d: %s done (%zu poses)\n", f.name.c_str(), poses.size());
	}

	Table csv;
	csv.columns = {"pair", "method", "ns_per_query", "max_point_error", "max_normal_error", "max_separation_error",
	               "failures", "queries", "compared", "x_bullet64"};
	Table md;
	md.columns = {"pair", "method", "ns/query", "× bullet64", "point error", "normal error", "separation error", "failures"};
	for (const Row& r : rows)
	{
		const bool none = r.errors.compared == 0;
		auto error = [none](double e, int digits) { return none ? std::string("n/a") : bench::FormatNumber(e, digits); };
		csv.rows.push_back({r.family, r.method, bench::FormatNumber(r.ns), error(r.errors.point, 3), error(r.errors.normal, 3),
		                    error(r.errors.separation, 3), std::to_string(r.errors.failures), std::to_string(r.queries),
		                    std::to_string(r.errors.compared), bench::FormatNumber(r.ratio)});
		md.rows.push_back({r.family, r.method, bench::FormatNumber(r.ns, 3), bench::FormatNumber(r.ratio, 3), error(r.errors.point, 2),
		                   error(r.errors.normal, 2), error(r.errors.separation, 2),
		                   std::to_string(r.errors.failures) + "/" + std::to_string(r.queries)});
	}
	WriteText(opt.out + "/pairs3d.csv", csv.Csv());
	std::string text = "# b2a_bench_pairs3d\n\n";
	text += "Machine: " + machine.cpu + ", " + std::to_string(machine.cores) + " hardware threads.  \n";
	text += "Build: " + machine.buildFlags + ".  \n";
	text += "Run: `b2a_bench_pairs3d" + std::string(opt.quick ? " --quick" : "") + " --seed " + std::to_string(opt.seed) + "`, " +
	        std::to_string(perClass) + " poses per class (separated, near-tangent, overlapping) and family, " +
	        std::to_string(motions) + " warm-start motions each, median of " + std::to_string(repeats) +
	        " repeats of the thread's CPU time.\n\n";
	text += "Errors are relative to the pair's size (mean bounding radius); normal errors in radians, against the "
	        "long-double reference contact. Our methods over all poses; Bullet's (GJK closest points, EPA "
	        "penetration, on the hull of N surface points, margin 0) over the near-tangent poses, with a wrong "
	        "verdict beyond its hull's own error counted as a failure. `× bullet64` is the time over "
	        "`bullet_gjk_epa64`'s on the same poses (a warm row's: the motions), the two timed in alternation in "
	        "every repeat: the median of the repeats' ratios (the grid rows: a third as many repeats).\n\n";
	text += md.Markdown();
	WriteText(opt.out + "/pairs3d.md", text);

	for (const Family& f : families)
	{
		std::vector<PairsPlotPoint> points;
		for (const Row& r : rows)
			if (r.family == f.name && r.errors.compared > 0)
				points.push_back({r.method, r.ns, r.errors.point});
		WriteText(opt.out + "/pairs3d_" + f.name + ".svg", PairsPlot(f.name, points));
	}
	const Row* summary = nullptr;
	for (const Row& r : rows)
		if (r.method == "auto_warm" && r.family.rfind("superellipsoid", 0) == 0 && !summary)
			summary = &r;
	if (!summary && !rows.empty())
		summary = &rows.front();
	std::printf("b2a_bench_pairs3d: %zu rows, %zu families in %.1f s; %s %s %.0f ns (%.2f x bullet_gjk_epa64), point error %.1e "
	            "-> %s/pairs3d.md\n",
	            rows.size(), families.size(), progress.Elapsed(), summary ? summary->family.c_str() : "-",
	            summary ? summary->method.c_str() : "-", summary ? summary->ns : 0.0, summary ? summary->ratio : 0.0,
	            summary ? summary->errors.point : 0.0, opt.out.c_str());
	return 0;
}
