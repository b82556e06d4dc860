// b2analytic benchmark: run time against error per shape pair, for each of our contact methods
// and for what a Box2D user would do instead, measured side by side in one process.
#include "BenchCommon.h"
#include "common/CommandLine.h"
#include "PairReference.h"
#include "PairsPlot.h"

#include "b2analytic/b2analytic.h"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
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

namespace
{
const char* kHelp = R"(b2a_bench_pairs: time against error per shape pair.

For each pair family (circles, ellipses of aspect 1.5 to 1000, superellipses with equal,
unequal and non-integer exponents, hearts) it poses pairs from a fixed seed: separated
(gaps of 2% to 50% of the size), near-tangent (gap below 1e-12 of the size) and overlapping
(1% to 25% of the size), and from each a sequence of small motions for warm starts. Every
method is timed over the same poses (median of repeats, nanoseconds of thread CPU time per
query, so that other work on the machine does not inflate it), in alternation with Box2D's
8-gons on those poses for its ratio to them (Box2D's methods are given the poses as its bodies
hold them, b2Transforms made with the poses and not timed), and its answers are compared with
long-double references:
  newton_cold, newton_warm  Newton on the common level (warm: carried along the motions)
  auto, auto_warm           the automatic path the Box2D adapter uses
  grid_<N>                  the paper's grid method with N samples, not refined
  grid_refined              the grid method (256 samples) refined between samples
  box2d_polygon8            b2CollidePolygons on inscribed 8-gons (Box2D's own narrow phase;
                            for hearts the hull of the 8-gon, a time baseline only)
  box2d_obb                 b2CollidePolygons on the oriented bounding boxes
  box2d_circle              b2CollideCircles (circle pairs)
  box2d_gjk<N>              b2Distance (GJK) on inscribed N-gons, N = 8 to 64
Errors, relative to the pair's size (the mean bounding radius): contact point, normal angle
(radians) and separation. Our methods against the reference of the level they solve (the
common level, or for the grid the one-sided level of the side it took, its verdict against
both sides); Box2D's over the near-tangent and overlapping poses it reports a contact for
(GJK: the near-tangent ones). failures: no answer, a non-finite one, a wrong verdict (the
plain grid calls near-tangent touching pairs apart), or (Box2D) a contact missed where the
shapes overlap; GJK reports no penetration, so every overlapping pose is a failure for it.

Writes DIR/pairs.csv, DIR/pairs.md and DIR/pairs_<family>.svg.
)";

// ------------------------------------------------------------------------------------------
// Pair families
// ------------------------------------------------------------------------------------------

/// One shape of a family, for the library and for the reference.
struct FamilyShape
{
	ShapePtr shape;
	RefShape ref;
	std::shared_ptr<test::ref::Curve> curve; // dense own-surface samples for the one-sided reference
};

struct Family
{
	std::string name;
	FamilyShape a, b;
	bool convex = true;  // both convex (common level, Box2D methods)
	bool smooth = true;  // both smooth and strictly convex (Newton)
	bool circles = false;
};

FamilyShape Super(double a, double b, double n, double m)
{
	FamilyShape s;
	s.shape = MakeSuperellipse(a, b, n, m);
	s.ref = RefShape::Super(a, b, n, m);
	return s;
}

FamilyShape Heart(double alpha)
{
	FamilyShape s;
	s.shape = MakeHeart(alpha);
	s.ref = RefShape::Heart(alpha);
	return s;
}

std::vector<Family> Families()
{
	std::vector<Family> f;
	auto add = [&](std::string name, FamilyShape a, FamilyShape b, bool convex = true) {
		Family fam;
		fam.name = std::move(name);
		fam.a = std::move(a);
		fam.b = std::move(b);
		fam.convex = convex;
		fam.smooth = convex;
		f.push_back(std::move(fam));
	};
	add("circle", Super(1.0, 1.0, 2, 2), Super(0.7, 0.7, 2, 2));
	f.back().a.shape = MakeCircle(1.0);
	f.back().b.shape = MakeCircle(0.7);
	f.back().circles = true;
	// Ellipses of growing aspect; the thin ones are made long rather than thin so that Box2D's
	// polygons (skin 0.01, vertices welded closer than 0.0025) can still represent them.
	add("ellipse_a1.5", Super(1.0, 1.0 / 1.5, 2, 2), Super(0.8, 0.8 / 1.5, 2, 2));
	add("ellipse_a3", Super(1.0, 1.0 / 3, 2, 2), Super(0.8, 0.8 / 3, 2, 2));
	add("ellipse_a10", Super(1.0, 0.1, 2, 2), Super(0.8, 0.08, 2, 2));
	add("ellipse_a100", Super(5.0, 0.05, 2, 2), Super(4.0, 0.04, 2, 2));
	add("ellipse_a1000", Super(20.0, 0.02, 2, 2), Super(16.0, 0.016, 2, 2));
	for (auto& fam : f)
		if (fam.name.rfind("ellipse", 0) == 0)
		{
			fam.a.shape = MakeEllipse(fam.a.ref.a, fam.a.ref.b);
			fam.b.shape = MakeEllipse(fam.b.ref.a, fam.b.ref.b);
		}
	add("superellipse_n4", Super(1.0, 0.6, 4, 4), Super(0.8, 0.5, 4, 4));
	add("superellipse_n8", Super(1.0, 0.6, 8, 8), Super(0.8, 0.5, 8, 8));
	add("superellipse_n12", Super(1.0, 0.6, 12, 12), Super(0.8, 0.5, 12, 12));
	add("superellipse_n4_m8", Super(1.0, 0.6, 4, 8), Super(0.8, 0.5, 4, 8));
	add("superellipse_n2.5_m3.7", Super(1.0, 0.6, 2.5, 3.7), Super(0.8, 0.5, 2.5, 3.7));
	add("heart_heart", Heart(1.0), Heart(0.7), false);
	add("heart_superellipse", Heart(1.0), Super(0.8, 0.5, 4, 4), false);
	// The heart-superellipse pair is not convex, but its superellipse is; the reference needs to
	// know per shape (line crossings of a convex shape are found beyond the line's minimum).
	return f;
}

bool IsConvexRef(const RefShape& s) { return s.kind == RefShape::Kind::superellipse; }

// ------------------------------------------------------------------------------------------
// Poses
// ------------------------------------------------------------------------------------------

enum class PoseClass { separated, nearTangent, overlapping };

struct PairPose
{
	Pose pa, pb;
	PoseClass cls;
	int sequence = -1; // -1: a base pose; else the index of its base pose (a warm-start motion)
	b2Transform xa, xb; // the poses as Box2D's bodies hold them, made with the poses, not timed
};

// A pose as a Box2D body holds it (float position and rotation).
b2Transform ToB2(const Pose& p)
{
	b2Transform xf;
	xf.Set(b2Vec2(float(p.p.x), float(p.p.y)), float(p.q.Angle()));
	return xf;
}

struct Reference
{
	RefContact common;  // convex families
	OneSidedRefs oneSided;
	bool hasCommon = false, hasOneSided = false;
};

double PairSize(const Family& f) { return 0.5 * (f.a.shape->BoundingRadius() + f.b.shape->BoundingRadius()); }

// B placed along direction u from A at the centre distance where the automatic contact's
// separation equals `gap` (bisection on the distance; the separation grows with it). The
// library only places the poses; every error is measured against the long-double reference.
// Where the separation jumps across the gap (a non-convex pair whose contact switches from one
// basin of the level to another: the two levels tie there), bisection would converge onto
// the jump, a pose whose answer is either basin to rounding; B is then moved on by 1e-3 of the
// size, where one basin is clearly lower.
Pose PlaceB(const Family& f, const Pose& pa, double angleB, Vec2 u, double gap)
{
	const double far = 1.05 * (f.a.shape->BoundingRadius() + f.b.shape->BoundingRadius()) + std::fabs(gap);
	auto sep = [&](double t) {
		return ComputeContact(*f.a.shape, pa, *f.b.shape, Pose(pa.p + t * u, angleB)).separation - gap;
	};
	double lo = 1e-6 * far, hi = far;
	if (sep(lo) > 0.0)
		return Pose(pa.p + lo * u, angleB);
	for (int i = 0; i < 100 && hi - lo > 1e-15 * far; ++i)
	{
		const double mid = 0.5 * (lo + hi);
		(sep(mid) < 0.0 ? lo : hi) = mid;
	}
	if (sep(hi) - sep(lo) > 1e-6 * far)
		return Pose(pa.p + (hi + 1e-3 * PairSize(f)) * u, angleB);
	return Pose(pa.p + 0.5 * (lo + hi) * u, angleB);
}

std::vector<PairPose> MakePoses(const Family& f, int perClass, int motions, std::mt19937_64& rng)
{
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	const double size = PairSize(f);
	std::vector<PairPose> poses;
	for (PoseClass cls : {PoseClass::separated, PoseClass::nearTangent, PoseClass::overlapping})
	{
		for (int k = 0; k < perClass; ++k)
		{
			const Pose pa(Vec2(unit(rng) - 0.5, unit(rng) - 0.5), 2.0 * kPi * unit(rng));
			const double dir = 2.0 * kPi * unit(rng), angleB = 2.0 * kPi * unit(rng);
			double gap = 0.0;
			if (cls == PoseClass::separated)
				gap = size * (0.02 + 0.48 * unit(rng));
			else if (cls == PoseClass::overlapping)
				gap = -size * (0.01 + 0.24 * unit(rng));
			const Pose pb = PlaceB(f, pa, angleB, Vec2(std::cos(dir), std::sin(dir)), gap);
			const int base = int(poses.size());
			poses.push_back({pa, pb, cls, -1, ToB2(pa), ToB2(pb)});
			// Small motions of B relative to A, as between time steps of a simulation: 0.1% of
			// the size and 1 mrad per step.
			Pose moved = pb;
			for (int s = 0; s < motions; ++s)
			{
				const Vec2 d(unit(rng) - 0.5, unit(rng) - 0.5);
				moved = Pose(moved.p + 2e-3 * size * d, moved.q.Angle() + 2e-3 * (unit(rng) - 0.5));
				poses.push_back({pa, moved, cls, base, ToB2(pa), ToB2(moved)});
			}
		}
	}
	return poses;
}

// ------------------------------------------------------------------------------------------
// Methods
// ------------------------------------------------------------------------------------------

/// What one method answered for one pose, in double.
struct Answer
{
	bool ok = false;
	bool contact = true; // false: the method says "no contact" (Box2D manifolds), nothing to compare
	Vec2 point, pointA, pointB, normal;
	double separation = 0.0;
	bool compareMidpoint = false; // Box2D: one point midway between the surfaces
	bool distanceOnly = false;    // GJK: a distance, no penetration; compared near tangency only
};

enum class Convention { common, oneSided, box2d };

struct Method
{
	std::string name;
	Convention convention;
	bool warm = false; // runs over the motion sequences, carrying a warm start
	std::function<void(const Family&, const std::vector<PairPose>&, const std::vector<int>&, std::vector<Answer>*)> run;
	bool timingOnly = false; // a timing baseline whose answers are not those of the pair (a heart's hull)
};

Answer FromContact(const ContactResult& c)
{
	Answer a;
	a.ok = c.Ok() && std::isfinite(c.separation) && IsFinite(c.pointA) && IsFinite(c.pointB) && IsFinite(c.normal);
	a.point = c.point;
	a.pointA = c.pointA;
	a.pointB = c.pointB;
	a.normal = c.normal;
	a.separation = c.separation;
	return a;
}

// N points of the shape's surface at evenly spaced polar angles, the polygon a Box2D user
// would build (inscribed: the vertices lie on the surface).
std::vector<b2Vec2> Polygonise(const Shape& s, int count)
{
	std::vector<b2Vec2> v(count);
	for (int k = 0; k < count; ++k)
	{
		const Vec2 p = s.SurfacePoint(2.0 * kPi * (k + 0.5) / count);
		v[k] = b2Vec2(float(p.x), float(p.y));
	}
	return v;
}

Answer FromManifold(const b2Manifold& m, const b2Transform& xa, float ra, const b2Transform& xb, float rb)
{
	Answer a;
	a.ok = true;
	a.compareMidpoint = true;
	if (m.pointCount == 0)
	{
		a.contact = false;
		return a;
	}
	b2WorldManifold wm;
	wm.Initialize(&m, xa, ra, xb, rb);
	int deepest = 0;
	for (int i = 1; i < m.pointCount; ++i)
		if (wm.separations[i] < wm.separations[deepest])
			deepest = i;
	a.point = Vec2(wm.points[deepest].x, wm.points[deepest].y);
	a.normal = Vec2(wm.normal.x, wm.normal.y);
	a.separation = wm.separations[deepest];
	a.ok = std::isfinite(a.separation) && IsFinite(a.point) && IsFinite(a.normal);
	return a;
}

std::vector<Method> Methods(const Family& f)
{
	std::vector<Method> methods;
	auto each = [](const std::vector<PairPose>& poses, const std::vector<int>& which, auto&& body) {
		for (size_t i = 0; i < which.size(); ++i)
			body(poses[which[i]], i);
	};
	auto contactMethod = [&](std::string name, Convention conv, MethodChoice choice, SolverOptions options) {
		methods.push_back({name, conv, false,
			[choice, options, each](const Family& fam, const std::vector<PairPose>& poses, const std::vector<int>& which,
			                        std::vector<Answer>* out) {
				each(poses, which, [&](const PairPose& p, size_t i) {
					const ContactResult c = ComputeContact(*fam.a.shape, p.pa, *fam.b.shape, p.pb, choice, options);
					KeepAlive(c);
					if (out)
						(*out)[i] = FromContact(c);
				});
			}});
	};
	// Warm start carried along a motion sequence (its base pose solved first, untimed order:
	// every pass starts each sequence from the same base solution, computed here once).
	auto warmMethod = [&](std::string name, MethodChoice choice) {
		auto bases = std::make_shared<std::map<int, WarmStart>>();
		methods.push_back({name, Convention::common, true,
			[choice, bases, each](const Family& fam, const std::vector<PairPose>& poses, const std::vector<int>& which,
			                      std::vector<Answer>* out) {
				WarmStart warm;
				int current = -2;
				each(poses, which, [&](const PairPose& p, size_t i) {
					if (p.sequence != current)
					{
						current = p.sequence;
						auto it = bases->find(current);
						if (it == bases->end())
						{
							WarmStart w;
							const PairPose& base = poses[current];
							ComputeContact(*fam.a.shape, base.pa, *fam.b.shape, base.pb, choice, {}, &w);
							it = bases->emplace(current, w).first;
						}
						warm = it->second;
					}
					const ContactResult c = ComputeContact(*fam.a.shape, p.pa, *fam.b.shape, p.pb, choice, {}, &warm);
					KeepAlive(c);
					if (out)
						(*out)[i] = FromContact(c);
				});
			}});
	};
	const Convention autoConv = f.convex ? Convention::common : Convention::oneSided;
	if (f.smooth)
	{
		contactMethod("newton_cold", Convention::common, MethodChoice::newton, {});
		warmMethod("newton_warm", MethodChoice::newton);
	}
	contactMethod("auto", autoConv, MethodChoice::automatic, {});
	if (f.convex)
		warmMethod("auto_warm", MethodChoice::automatic);
	for (int samples : {64, 256, 1024, 4096})
	{
		SolverOptions o;
		o.gridSamples = samples;
		o.gridRefine = false;
		contactMethod("grid_" + std::to_string(samples), Convention::oneSided, MethodChoice::grid, o);
	}
	contactMethod("grid_refined", Convention::oneSided, MethodChoice::grid, {});
	if (f.circles)
	{
		auto ca = std::make_shared<b2CircleShape>(), cb = std::make_shared<b2CircleShape>();
		ca->m_radius = float(f.a.shape->BoundingRadius());
		cb->m_radius = float(f.b.shape->BoundingRadius());
		methods.push_back({"box2d_circle", Convention::box2d, false,
			[ca, cb, each](const Family&, const std::vector<PairPose>& poses, const std::vector<int>& which,
			               std::vector<Answer>* out) {
				each(poses, which, [&](const PairPose& p, size_t i) {
					const b2Transform &xa = p.xa, &xb = p.xb;
					b2Manifold m;
					b2CollideCircles(&m, ca.get(), xa, cb.get(), xb);
					KeepAlive(m);
					if (out)
						(*out)[i] = FromManifold(m, xa, ca->m_radius, xb, cb->m_radius);
				});
			}});
	}
	auto polygonMethod = [&](std::string name, std::shared_ptr<b2PolygonShape> pa, std::shared_ptr<b2PolygonShape> pb) {
		methods.push_back({name, Convention::box2d, false,
			[pa, pb, each](const Family&, const std::vector<PairPose>& poses, const std::vector<int>& which,
			               std::vector<Answer>* out) {
				each(poses, which, [&](const PairPose& p, size_t i) {
					const b2Transform &xa = p.xa, &xb = p.xb;
					b2Manifold m;
					b2CollidePolygons(&m, pa.get(), xa, pb.get(), xb);
					KeepAlive(m);
					if (out)
						(*out)[i] = FromManifold(m, xa, pa->m_radius, xb, pb->m_radius);
				});
			}});
	};
	auto octagon = [](const Shape& s) {
		auto p = std::make_shared<b2PolygonShape>();
		const auto v = Polygonise(s, 8);
		p->Set(v.data(), 8);
		return p;
	};
	polygonMethod("box2d_polygon8", octagon(*f.a.shape), octagon(*f.b.shape));
	if (!f.convex)
	{
		// A heart has no convex polygon (a Box2D user would decompose it into several): its
		// 8-gon, the hull of the inscribed vertices (b2PolygonShape::Set takes the hull), is the
		// target's time baseline only, and its answers, the hull's, are not compared.
		methods.back().timingOnly = true;
		return methods;
	}
	auto box = [](const Shape& s) {
		auto p = std::make_shared<b2PolygonShape>();
		const Box bounds = s.ComputeAABB(Pose());
		p->SetAsBox(float(0.5 * (bounds.upper.x - bounds.lower.x)), float(0.5 * (bounds.upper.y - bounds.lower.y)));
		return p;
	};
	polygonMethod("box2d_obb", box(*f.a.shape), box(*f.b.shape));
	for (int count : {8, 16, 32, 64})
	{
		auto va = std::make_shared<std::vector<b2Vec2>>(Polygonise(*f.a.shape, count));
		auto vb = std::make_shared<std::vector<b2Vec2>>(Polygonise(*f.b.shape, count));
		methods.push_back({"box2d_gjk" + std::to_string(count), Convention::box2d, false,
			[va, vb, each](const Family&, const std::vector<PairPose>& poses, const std::vector<int>& which,
			               std::vector<Answer>* out) {
				b2DistanceInput input;
				input.proxyA.Set(va->data(), int32(va->size()), 0.0f);
				input.proxyB.Set(vb->data(), int32(vb->size()), 0.0f);
				input.useRadii = false;
				each(poses, which, [&](const PairPose& p, size_t i) {
					input.transformA = p.xa;
					input.transformB = p.xb;
					b2SimplexCache cache;
					cache.count = 0;
					b2DistanceOutput o;
					b2Distance(&o, &cache, &input);
					KeepAlive(o);
					if (out)
					{
						Answer& a = (*out)[i];
						a.compareMidpoint = true;
						a.distanceOnly = true;
						// GJK gives the distance of separated shapes only: overlapping ones
						// report 0 and no normal.
						a.ok = o.distance > 0.0f;
						if (a.ok)
						{
							const Vec2 pA(o.pointA.x, o.pointA.y), pB(o.pointB.x, o.pointB.y);
							a.point = 0.5 * (pA + pB);
							a.normal = (1.0 / o.distance) * (pB - pA);
							a.separation = o.distance;
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

double AngleBetween(Vec2 a, V b)
{
	const double bx = double(b.x), by = double(b.y);
	return std::atan2(std::fabs(a.x * by - a.y * bx), a.x * bx + a.y * by);
}

double DistanceL(Vec2 a, V b) { return double(test::ref::Dist(a, b)); }

void Accumulate(const Answer& ans, const RefContact& ref, PoseClass cls, Convention conv, double size, Errors& e)
{
	const bool refOverlap = ref.separation < 0.0L;
	if (!ans.ok)
	{
		++e.failures;
		return;
	}
	if (conv == Convention::box2d)
	{
		if (!ans.contact)
		{
			if (refOverlap || cls == PoseClass::nearTangent)
				++e.failures; // a missed contact: the true shapes touch
			return;
		}
		// Manifolds exist only within the skin; a GJK distance away from tangency is the
		// Euclidean gap, which differs from the level contact's gap along its normal at second
		// order, so GJK is compared near tangency only.
		if (cls == PoseClass::separated || (ans.distanceOnly && cls != PoseClass::nearTangent))
			return;

		const V mid = 0.5L * (ref.pointA + ref.pointB);
		e.point = std::fmax(e.point, DistanceL(ans.point, mid) / size);
	}
	else
	{
		e.point = std::fmax(e.point, std::fmax(DistanceL(ans.pointA, ref.pointA), DistanceL(ans.pointB, ref.pointB)) / size);
	}
	e.normal = std::fmax(e.normal, AngleBetween(ans.normal, ref.normal));
	e.separation = std::fmax(e.separation, std::fabs(double(LD(ans.separation) - ref.separation)) / size);
	++e.compared;
}

// A grid contact is one-sided, on the side ChooseGridSide picks (both ways, the touching or
// nearer answer, where it must): its errors are those against the reference of the side it
// took, the one its points lie nearer, and its verdict is checked against both sides (the
// pair overlaps when either does): a wrong one is a failure.
void AccumulateOneSided(const Answer& ans, const OneSidedRefs& refs, PoseClass cls, double size, Errors& e)
{
	if (!ans.ok || (ans.separation <= 0.0) != refs.touching)
	{
		++e.failures;
		return;
	}
	auto off = [&](const RefContact& r) { return std::fmax(DistanceL(ans.pointA, r.pointA), DistanceL(ans.pointB, r.pointB)); };
	Accumulate(ans, off(refs.aOntoB) <= off(refs.bOntoA) ? refs.aOntoB : refs.bOntoA, cls, Convention::oneSided, size, e);
}

struct Row
{
	std::string family, method;
	double ns = 0.0;
	double ratio = std::nan(""); // time over box2d_polygon8's on the same poses (NaN: no 8-gon baseline)
	bool timingOnly = false; // a time baseline only: no errors, no failures
	Errors errors;
	int queries = 0;
};

} // namespace

int main(int argc, char** argv)
{
	std::vector<Family> families = Families();
	std::vector<std::string> allNames, familyNames;
	for (const Family& f : families)
		allNames.push_back(f.name);
	int perClass = 0, repeats = 0;
	CommandLine cli("b2a_bench_pairs", kHelp);
	cli.Add("--poses", perClass, 40, 8, "N", "poses per class and family (default 40, quick 8)", WholeNumber(1, 100000));
	cli.Add("--repeats", repeats, 9, 3, "N", "repeats of each timing, of which the median is reported (default 9, quick 3)", WholeNumber(1, 1000));
	cli.Add("--families", familyNames, "NAME,NAME",
	        "only these pair families, e.g. ellipse_a3,superellipse_n4 (default all);\n"
	        "each family's poses are those of the full run, from its own generator\n"
	        "seeded by --seed and its name",
	        OneOf(allNames));
	const DemoOptions opt = cli.Parse(argc, argv);
	const int motions = opt.quick ? 4 : 8;
	const MachineInfo machine = GetMachineInfo();
	Progress progress("b2a_bench_pairs");

	SelectFamilies(families, familyNames); // in the table's order
	std::vector<Row> rows;
	for (size_t fi = 0; fi < families.size(); ++fi)
	{
		Family& f = families[fi];
		for (FamilyShape* s : {&f.a, &f.b})
			s->curve = std::make_shared<test::ref::Curve>(
				test::ref::SampleCurve(s->ref, s->ref.Own(), s->ref.kind == RefShape::Kind::heart ? 20000 : 8192));
		const double size = PairSize(f);
		std::mt19937_64 rng = FamilyRng(opt.seed, f.name);
		const std::vector<PairPose> poses = MakePoses(f, perClass, motions, rng);
		std::vector<int> base, moved;
		for (size_t i = 0; i < poses.size(); ++i)
			(poses[i].sequence < 0 ? base : moved).push_back(int(i));

		// References: the one-sided one for the base poses (grid methods and non-convex
		// families), the common one for every pose of a convex family.
		progress.Report(double(fi) / families.size(), f.name + ": references");
		std::vector<Reference> refs(poses.size());
		for (size_t i = 0; i < poses.size(); ++i)
		{
			const RefPosed A{f.a.ref, test::ref::Of(poses[i].pa), f.a.shape->BoundingRadius(), f.a.curve.get()};
			const RefPosed B{f.b.ref, test::ref::Of(poses[i].pb), f.b.shape->BoundingRadius(), f.b.curve.get()};
			if (f.convex)
			{
				refs[i].common = CommonContactRef(A, B);
				refs[i].hasCommon = true;
			}
			if (poses[i].sequence < 0 || !f.convex)
			{
				refs[i].oneSided = OneSidedContactRefs(A, B, IsConvexRef(f.a.ref), IsConvexRef(f.b.ref));
				refs[i].hasOneSided = true;
			}
		}

		progress.Report((fi + 0.5) / families.size(), f.name + ": timing");
		const std::vector<Method> methods = Methods(f);
		const Method* polygon8 = nullptr;
		for (const Method& m : methods)
			if (m.name == "box2d_polygon8")
				polygon8 = &m;
		for (const Method& m : methods)
		{
			const std::vector<int>& which = m.warm ? moved : base;
			std::vector<Answer> answers(which.size());
			m.run(f, poses, which, &answers);
			Row row;
			row.family = f.name;
			row.method = m.name;
			row.queries = int(which.size());
			row.timingOnly = m.timingOnly;
			for (size_t i = 0; i < which.size() && !m.timingOnly; ++i)
			{
				const Reference& r = refs[which[i]];
				if (m.convention == Convention::oneSided)
					AccumulateOneSided(answers[i], r.oneSided, poses[which[i]].cls, size, row.errors);
				else
					Accumulate(answers[i], r.common, poses[which[i]].cls, m.convention, size, row.errors);
			}
			// Each method against the 8-gons on its own poses (a warm row's are the motions), the
			// two timed in alternation, so that the ratio, the target's measure, does not take
			// the machine's drift between rows.
			const auto pass = [&] { m.run(f, poses, which, nullptr); };
			const PairedTiming t = TimeAgainstBaseline(
				pass, [&] { polygon8->run(f, poses, which, nullptr); }, !polygon8 || &m == polygon8, int(which.size()), repeats);
			row.ns = t.ns;
			row.ratio = polygon8 ? t.ratio : std::nan("");
			rows.push_back(row);
		}
		std::fprintf(stderr, "b2a_bench_pairs: %s done (%zu poses)\n", f.name.c_str(), poses.size());
	}

	// Output: CSV, Markdown with ratios to box2d_polygon8, one plot per family.
	Table csv;
	csv.columns = {"pair", "method", "ns_per_query", "max_point_error", "max_normal_error", "max_separation_error",
	               "failures", "queries", "compared", "x_polygon8"};
	Table md;
	md.columns = {"pair", "method", "ns/query", "× polygon8", "point error", "normal error", "separation error",
	              "failures"};
	for (const Row& r : rows)
	{
		// No answer to compare (every contact missed): the errors are unknown, not zero.
		const bool none = r.errors.compared == 0;
		auto error = [none](double e, int digits) { return none ? std::string("n/a") : bench::FormatNumber(e, digits); };
		csv.rows.push_back({r.family, r.method, bench::FormatNumber(r.ns), error(r.errors.point, 3),
		                    error(r.errors.normal, 3), error(r.errors.separation, 3),
		                    r.timingOnly ? std::string() : std::to_string(r.errors.failures), std::to_string(r.queries),
		                    std::to_string(r.errors.compared),
		                    std::isnan(r.ratio) ? "" : bench::FormatNumber(r.ratio)});
		md.rows.push_back({r.family, r.method, bench::FormatNumber(r.ns, 3),
		                   std::isnan(r.ratio) ? "–" : bench::FormatNumber(r.ratio, 3),
		                   error(r.errors.point, 2), error(r.errors.normal, 2), error(r.errors.separation, 2),
		                   r.timingOnly ? std::string("–") : std::to_string(r.errors.failures) + "/" + std::to_string(r.queries)});
	}
	WriteText(opt.out + "/pairs.csv", csv.Csv());
	std::string text = "# b2a_bench_pairs\n\n";
	text += "Machine: " + machine.cpu + ", " + std::to_string(machine.cores) + " hardware threads.  \n";
	text += "Build: " + machine.buildFlags + ".  \n";
	text += "Run: `b2a_bench_pairs" + std::string(opt.quick ? " --quick" : "") + " --seed " + std::to_string(opt.seed) +
	        "`, " + std::to_string(perClass) + " poses per class (separated, near-tangent, overlapping) and family, " +
	        std::to_string(motions) + " warm-start motions each, median of " + std::to_string(repeats) +
	        " repeats of the thread's CPU time.\n\n";
	text += "Errors are relative to the pair's size (mean bounding radius); normal errors in radians. Our methods "
	        "are compared over all poses with the long-double reference of the level they solve (a grid contact, "
	        "one-sided, with that of the side it took, and a wrong verdict, against both sides, is a failure); "
	        "Box2D's over the "
	        "near-tangent and overlapping poses it reports a contact for (its point: the deepest manifold point, "
	        "midway between the surfaces, against the midpoint of the reference points; skin included, as a Box2D "
	        "user gets it), GJK's over the near-tangent ones (it gives no penetration, so an overlapping pose is a failure for it); a missed contact (the true shapes touch) is a failure. `× polygon8` is the time over "
	        "`box2d_polygon8`'s (b2CollidePolygons on inscribed 8-gons; for a heart, which has no convex polygon, "
	        "the hull of its inscribed 8-gon, a time baseline only) on the same poses (a warm row's: the motions), "
	        "given as Box2D's bodies hold them (b2Transforms made with the poses, not timed: before 2026-12-05 the "
	        "conversion, an atan2 and a float sine and cosine, was timed with it, a third of its time), "
	        "the two timed in alternation, one right after the other in every repeat: the median of the repeats' "
	        "ratios, so that the machine's drift between rows cancels.\n\n";
	text += md.Markdown();
	WriteText(opt.out + "/pairs.md", text);

	for (const Family& f : families)
	{
		std::vector<bench::PairsPlotPoint> points;
		for (const Row& r : rows)
			if (r.family == f.name && r.errors.compared > 0)
				points.push_back({r.method, r.ns, r.errors.point});
		WriteText(opt.out + "/pairs_" + f.name + ".svg", bench::PairsPlot(f.name, points));
	}

	const auto find = [&](const std::string& fam, const std::string& method) -> const Row* {
		for (const Row& r : rows)
			if (r.family == fam && r.method == method)
				return &r;
		return nullptr;
	};
	// The one-line summary names the first family's warm automatic path (or its automatic one,
	// for hearts), so that it means something whichever families ran.
	const std::string first = rows.empty() ? std::string() : rows.front().family;
	const Row* e = find(first, "auto_warm");
	if (!e)
		e = find(first, "auto");
	std::printf("b2a_bench_pairs: %zu rows, %zu families in %.1f s; %s %s %.0f ns", rows.size(), families.size(),
	            progress.Elapsed(), first.c_str(), e ? e->method.c_str() : "-", e ? e->ns : 0.0);
	if (e && !std::isnan(e->ratio))
		std::printf(" (%.2f x polygon8)", e->ratio);
	std::printf(", point error %.1e -> %s/pairs.md\n", e ? e->errors.point : 0.0, opt.out.c_str());
	return 0;
}
