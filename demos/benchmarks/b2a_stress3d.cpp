// b2analytic benchmark: numerical stability of the 3D contact solvers over random pairs.
//
// Most configurations are built with a known answer: A at a random pose, a point X on A's
// level-C surface, and B turned and placed so that its own level-C surface touches A's there
// with opposed normals. For convex shapes that point is the common level's unique solution, so
// the answer is known exactly (to the construction's rounding, ~1e-16) without any solver.
// Random poses are checked by a long-double Newton polish of the equations from the answer.
#include "BenchCommon.h"
#include "common/CommandLine.h"

#include "b2analytic/3d/Contact3.h"
#include "b2analytic/3d/SuperellipsoidShape.h"
#include "Reference3.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace b2a;
using demo::Json;
namespace r3 = b2a::test::ref3;

namespace
{
const char* kHelp = R"(b2a_stress3d: numerical stability of the 3D contact solvers on random pairs.

A million configurations (--quick: 40000) of superellipsoids, ellipsoids and spheres (aspect
ratio 1 to 100, exponents 2 to 20, integer or not and unequal, sizes 1e-3 to 1e3 with a size
ratio up to 10), most built with a known common level C and point: log-uniform C from 1e-3 to
1e3 (built), |C - 1| below 1e-9 (near_tangent), C from 1e-6 to 1e-2 (deep_overlap, one centre
deep inside the other), the same shape twice (identical); and the same shape at the same pose
(identical_pose) or two shapes at one centre (coincident), which have no level point and get
the axis of least overlap; and random poses (random, checked by a long-double Newton polish of
the equations from the answer). Each is solved by ComputeContact (the automatic path); each
built pair is then solved warm-started after each of 3 small motions (turns and shifts of 1e-6 to
1e-2 of a radian or of the size, the level moved as much, rebuilt with its known answer), as the
Box2D adapter carries a contact's warm start from step to step.

The headline, "in_range" (neither centre inside the other particle) and "warm_in_range": how many
failed, gave a non-finite field or the wrong touching verdict, and how many answers reported as
converged are not solutions (level off by more than 1e-9 relative, normal by more than 1e-6 rad),
with the worst level, point and normal errors and the worst cases in full precision. Pairs with a
centre inside the other are reported apart ("beyond_range_centre_inside", and warm).

Writes DIR/stress3d_summary.json (per category: how many converged, converged after a fallback,
failed, gave a non-finite field or a wrong verdict, the largest level, point and normal errors,
how many were inaccurate beyond 1e-9 of the level or the size, the mean time of a contact, and
the worst case in full precision). Flat contacts (faces of high exponents touching face to
face, whose point the equations' rounding moves by more than 1e-9 of the size) and random poses
at a common level below 1e-9 (centres within a hair of each other) are counted apart as
ill_conditioned, their errors reported separately (a flat contact's level and normal are still
checked).
Exits 1 when any result fails, has a non-finite field, or gives the wrong touching verdict, or
when an answer in range (cold or warm) has a wrong level or normal.
)";

// Warm-started solves after each built pair's cold one, each after a small motion.
constexpr int kWarmSteps = 3;

enum class Category : int { built, nearTangent, deepOverlap, identical, identicalPose, coincident, random, count };
const char* CategoryName(Category c)
{
	static const char* names[] = {"built", "near_tangent", "deep_overlap", "identical", "identical_pose", "coincident", "random"};
	return names[int(c)];
}

struct Tally
{
	long configurations = 0, converged = 0, fallback = 0, failed = 0, nonFinite = 0, wrongVerdict = 0, inaccurate = 0, checked = 0;
	double worstLevel = 0.0, worstPoint = 0.0, worstNormal = 0.0;
	Json worstCase;
	double worstScore = -1.0;
	long flat = 0;                     // ill-conditioned configurations (flat faces, near-coincident centres), apart
	double flatLevel = 0.0, flatPoint = 0.0;
	double seconds = 0.0;              // time in ComputeContact
	std::map<std::string, long> methods; // answers per solver
	std::map<std::string, double> methodSeconds;
};

struct Random
{
	std::mt19937_64 engine;
	double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
	double LogUniform(double lo, double hi) { return std::exp(Uniform(std::log(lo), std::log(hi))); }
	Vec3 Unit()
	{
		std::normal_distribution<double> n(0.0, 1.0);
		return Normalize(Vec3(n(engine), n(engine), n(engine)));
	}
	Quat Rotation()
	{
		std::normal_distribution<double> n(0.0, 1.0);
		return Normalize(Quat(n(engine), n(engine), n(engine), n(engine)));
	}
};

std::shared_ptr<SuperellipsoidShape> RandomShape(Random& rng, double scale)
{
	const double a = scale, b = scale * rng.LogUniform(0.1, 10.0), c = scale * rng.LogUniform(0.1, 10.0);
	// Aspect at most 100 between the largest and smallest semi-axis.
	const double lo = std::min({a, b, c}), hi = std::max({a, b, c});
	const double squeeze = hi / lo > 100.0 ? std::log(100.0) / std::log(hi / lo) : 1.0;
	auto axis = [&](double v) { return lo * std::pow(v / lo, squeeze); };
	const double roll = rng.Uniform(0, 1);
	if (roll < 0.1)
		return MakeSphere(a);
	if (roll < 0.25)
		return MakeEllipsoid(axis(a), axis(b), axis(c));
	auto exponent = [&]() { return rng.Uniform(0, 1) < 0.5 ? std::round(rng.Uniform(2, 20)) : rng.Uniform(2, 20); };
	const double n1 = exponent();
	const bool equal = rng.Uniform(0, 1) < 0.3;
	return MakeSuperellipsoid(axis(a), axis(b), axis(c), n1, equal ? n1 : exponent(), equal ? n1 : exponent());
}

// The rotation taking the unit u onto the unit v (the shortest arc).
Quat Arc(Vec3 u, Vec3 v)
{
	const double d = Dot(u, v);
	if (d < -1.0 + 1e-12)
	{
		Vec3 axis = Cross(u, Vec3(1, 0, 0));
		if (LengthSquared(axis) < 1e-6)
			axis = Cross(u, Vec3(0, 1, 0));
		return AxisAngle(axis, kPi);
	}
	const Vec3 c = Cross(u, v);
	return Normalize(Quat(1.0 + d, c.x, c.y, c.z));
}

// What a built pair is made of: A's pose, the directions of the touching point from each
// shape's centre, B's turn about the normal and the common level. A warm step perturbs them.
struct BuildParams
{
	Pose3 poseA;
	Vec3 rayA, rayB;
	double turn = 0.0, level = 1.0;
};

BuildParams DrawBuild(Random& rng, const SuperellipsoidShape& a, double C)
{
	BuildParams q;
	q.poseA = Pose3(Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)) * a.BoundingRadius(), rng.Rotation());
	q.rayA = rng.Unit();
	q.rayB = rng.Unit();
	q.turn = rng.Uniform(-kPi, kPi);
	q.level = C;
	return q;
}

// A small motion of a built pair, as between two steps of a simulation: everything turns or moves
// by about `delta` (radians, or relative to the size); the level by at most `levelDelta` relative.
BuildParams Perturb(Random& rng, BuildParams q, double size, double delta, double levelDelta)
{
	q.poseA = Pose3(q.poseA.p + delta * size * rng.Unit(), Normalize(AxisAngle(rng.Unit(), delta) * q.poseA.q));
	q.rayA = Normalize(q.rayA + delta * rng.Unit());
	q.rayB = Normalize(q.rayB + delta * rng.Unit());
	q.turn += delta * rng.Uniform(-1, 1);
	q.level *= 1.0 + levelDelta * rng.Uniform(-1, 1);
	return q;
}

// A pair built with common level C at the world point X, A's outward normal n there.
struct Built
{
	std::shared_ptr<SuperellipsoidShape> a, b;
	Pose3 pa, pb;
	double level = 0.0;
	Vec3 point, normal;
};

Built Build(std::shared_ptr<SuperellipsoidShape> a, std::shared_ptr<SuperellipsoidShape> b, const BuildParams& q)
{
	Built p;
	p.a = std::move(a);
	p.b = std::move(b);
	p.level = q.level;
	p.pa = q.poseA;
	const Vec3 xa = p.a->PointOnRay(q.rayA, q.level);
	p.point = ToWorld(p.pa, xa);
	p.normal = Normalize(Rotate(p.pa.q, p.a->Gradient(xa)));
	const Vec3 xb = p.b->PointOnRay(q.rayB, q.level);
	const Vec3 nb = Normalize(p.b->Gradient(xb));
	// B's outward normal at xb onto −n, then a turn about −n.
	const Quat rot = Normalize(AxisAngle(-p.normal, q.turn) * Arc(nb, -p.normal));
	p.pb = Pose3(p.point - Rotate(rot, xb), rot);
	return p;
}

double Angle(Vec3 a, Vec3 b) { return std::atan2(Length(Cross(a, b)), Dot(a, b)); }

// How far the common level's point is determined along the surfaces: the solvers fix it by the
// tangential part of ∇λA + μ∇λB = 0, whose rounding (a few eps of |∇λA|) moves the point by that
// over κ, the least eigenvalue on the tangent plane of H = H_A + μH_B (world, μ balancing the
// gradients). Flat faces of high exponents touching face to face have κ near 0: their point is
// not determined to the tolerance, only their level is.
double PointUncertainty(const Built& p)
{
	const Vec3 xa = ToBody(p.pa, p.point), xb = ToBody(p.pb, p.point);
	const LevelDerivatives3 da = p.a->Derivatives(xa), db = p.b->Derivatives(xb);
	const double mu = Length(da.gradient) / Length(db.gradient);
	const Sym33 H = Rotate(ToMatrix(p.pa.q), da.hessian) + mu * Rotate(ToMatrix(p.pb.q), db.hessian);
	// An orthonormal basis (t1, t2) of the tangent plane, and the 2×2 block's least eigenvalue.
	const Vec3 n = p.normal;
	const Vec3 t1 = Normalize(Cross(n, std::fabs(n.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0))), t2 = Cross(n, t1);
	const double h11 = Dot(t1, H * t1), h12 = Dot(t1, H * t2), h22 = Dot(t2, H * t2);
	const double kappa = 0.5 * (h11 + h22) - std::sqrt(0.25 * (h11 - h22) * (h11 - h22) + h12 * h12);
	return 1e-14 * Length(da.gradient) / std::max(kappa, 1e-300);
}

bool AllFinite(const ContactResult3& c)
{
	return std::isfinite(c.level) && std::isfinite(c.separation) && IsFinite(c.point) && IsFinite(c.normal) && IsFinite(c.pointA) &&
	       IsFinite(c.pointB);
}

Json VecJson(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

Json CaseJson(const SuperellipsoidShape& a, const Pose3& pa, const SuperellipsoidShape& b, const Pose3& pb, const ContactResult3& c)
{
	return {{"a", a.Describe()},
	        {"pose_a", {{"p", VecJson(pa.p)}, {"q", Json::array({pa.q.w, pa.q.x, pa.q.y, pa.q.z})}}},
	        {"b", b.Describe()},
	        {"pose_b", {{"p", VecJson(pb.p)}, {"q", Json::array({pb.q.w, pb.q.x, pb.q.y, pb.q.z})}}},
	        {"status", StatusName(c.status)},
	        {"method", MethodName(c.method)},
	        {"failure", c.failure},
	        {"level", c.level},
	        {"point", VecJson(c.point)}};
}

// Records what every result must satisfy: an answer, finite fields, the verdict its level gives.
bool Basic(Tally& t, const ContactResult3& c)
{
	++t.configurations;
	++t.methods[MethodName(c.method)];
	if (!c.Ok())
	{
		++t.failed;
		return false;
	}
	(c.status == SolveStatus::converged ? t.converged : t.fallback)++;
	if (!AllFinite(c))
	{
		++t.nonFinite;
		return false;
	}
	if (c.method != SolveMethod::overlapAxis && (c.touching != (c.level <= 1.0) || c.touching != (c.separation <= 0.0)))
	{
		++t.wrongVerdict;
		return false;
	}
	return true;
}

// The automatic contact, timed, with Basic's checks; a failing one becomes the category's worst.
bool Solve(Tally& t, const SuperellipsoidShape& a, const Pose3& pa, const SuperellipsoidShape& b, const Pose3& pb, ContactResult3& c,
           WarmStart3* warm = nullptr)
{
	// The thread's CPU time, which other work on the machine does not inflate.
	const double start = bench::ThreadCpuNanoseconds();
	c = ComputeContact(a, pa, b, pb, MethodChoice::automatic, {}, warm);
	const double spent = 1e-9 * (bench::ThreadCpuNanoseconds() - start);
	t.seconds += spent;
	t.methodSeconds[MethodName(c.method)] += spent;
	if (Basic(t, c))
		return true;
	if (t.worstScore < 1e300)
	{
		t.worstScore = 1e300;
		t.worstCase = CaseJson(a, pa, b, pb, c);
	}
	return false;
}

// What a user needs to know about one group of configurations (in range, beyond it, warm
// starts): failures, wrong verdicts, and answers reported as converged that are not solutions
// (level off by more than 1e-9 relative, normal by more than 1e-6 rad), with the worst errors.
struct Headline
{
	long configurations = 0, failed = 0, nonFinite = 0, wrongVerdicts = 0, checked = 0, wrongLevels = 0, wrongNormals = 0;
	long flat = 0; // flat contacts: the point is not determined (level and normal still checked)
	double worstLevel = 0.0, worstPoint = 0.0, worstNormal = 0.0;
	Json worstLevelCase, worstNormalCase, wrongVerdictCase;

	// The failure counts a configuration added to its category's tally.
	void CountOutcome(const Tally& before, const Tally& after)
	{
		++configurations;
		failed += after.failed - before.failed;
		nonFinite += after.nonFinite - before.nonFinite;
		wrongVerdicts += after.wrongVerdict - before.wrongVerdict;
	}

	void CountErrors(double level, double point, double normal, bool isFlat, const Json& which)
	{
		++checked;
		flat += isFlat ? 1 : 0;
		if (level > 1e-9)
			++wrongLevels;
		if (normal > 1e-6)
			++wrongNormals;
		if (level > worstLevel)
		{
			worstLevel = level;
			worstLevelCase = which;
		}
		if (normal > worstNormal)
		{
			worstNormal = normal;
			worstNormalCase = which;
		}
		if (!isFlat)
			worstPoint = std::max(worstPoint, point);
	}

	Json ToJson() const
	{
		return {{"configurations", configurations},
		        {"failed", failed},
		        {"non_finite", nonFinite},
		        {"wrong_verdicts", wrongVerdicts},
		        {"checked", checked},
		        {"wrong_levels_beyond_1e-9", wrongLevels},
		        {"wrong_normals_beyond_1e-6_rad", wrongNormals},
		        {"flat_contacts_point_not_determined", flat},
		        {"max_level_error", worstLevel},
		        {"max_point_error_where_determined", worstPoint},
		        {"max_normal_error", worstNormal},
		        {"worst_level_case", worstLevelCase},
		        {"worst_normal_case", worstNormalCase},
		        {"a_wrong_verdict_case", wrongVerdictCase}};
	}

	bool Clean() const { return failed + nonFinite + wrongVerdicts + wrongLevels + wrongNormals == 0; }
};

// A centre inside the other particle (or on its surface): beyond the range the headline covers.
bool CentreInside(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb)
{
	return a.Level(ToBody(pa, pb.p)) <= a.SurfaceLevel() || b.Level(ToBody(pb, pa.p)) <= b.SurfaceLevel();
}

void Errors(Tally& t, Headline& h, double level, double point, double normal, bool flat, const Json& which)
{
	h.CountErrors(level, point, normal, flat, which);
	++t.checked;
	t.worstLevel = std::max(t.worstLevel, level);
	t.worstPoint = std::max(t.worstPoint, point);
	t.worstNormal = std::max(t.worstNormal, normal);
	if (level > 1e-9 || point > 1e-9)
		++t.inaccurate;
	const double score = std::max(level, point);
	if (score > t.worstScore)
	{
		t.worstScore = score;
		t.worstCase = which;
	}
}
// The touching verdict against a built pair's level. Within rounding of tangency either verdict
// is right: the world coordinates, up to `reach`, are rounded to eps·reach, which moves a level by
// eps·reach·|∇λ|; as in b2a_stress, a verdict is judged only where |C − 1| exceeds 1e3 times that.
bool WrongVerdict(const Built& p, const ContactResult3& c)
{
	if ((p.level <= 1.0) == c.touching)
		return false;
	const double reach = std::max({Length(p.point), Length(p.pa.p), Length(p.pb.p)});
	const double slope = std::max(Length(p.a->Gradient(ToBody(p.pa, p.point))), Length(p.b->Gradient(ToBody(p.pb, p.point))));
	return std::fabs(p.level - 1.0) > 1e3 * std::numeric_limits<double>::epsilon() * reach * slope;
}

// A built pair's case with its known answer.
Json CaseWithAnswer(const Built& p, const ContactResult3& c)
{
	Json which = CaseJson(*p.a, p.pa, *p.b, p.pb, c);
	which["exact_level"] = p.level;
	which["exact_point"] = VecJson(p.point);
	return which;
}

// A built pair's answer against its construction: level, point (where the equations determine
// it) and normal.
void CheckBuilt(Tally& t, Headline& h, const Built& p, const ContactResult3& c)
{
	const double size = 0.5 * (p.a->BoundingRadius() + p.b->BoundingRadius());
	const Json which = CaseWithAnswer(p, c);
	const double levelError = std::fabs(c.level - p.level) / p.level, pointError = Distance(c.point, p.point) / size;
	const double normalError = Angle(c.normal, p.normal);
	if (PointUncertainty(p) > 1e-9 * size)
	{
		// A flat contact: its level and normal are checked, its point only as far as it is determined.
		++t.flat;
		t.flatLevel = std::max(t.flatLevel, levelError);
		t.flatPoint = std::max(t.flatPoint, pointError);
		Errors(t, h, levelError, 0.0, normalError, true, which);
	}
	else
		Errors(t, h, levelError, pointError, normalError, false, which);
}

// The run's state: the random streams, a tally per category (cold and warm), the headlines.
struct Stress
{
	Random rng, warmRng;
	std::vector<Tally> tallies = std::vector<Tally>(int(Category::count)), warmTallies = std::vector<Tally>(int(Category::count));
	Headline inRange, beyondRange, warmInRange, warmBeyondRange;

	// The warm motions draw from their own stream, so the cold pairs are those of a run without them.
	explicit Stress(std::uint64_t seed) : rng{std::mt19937_64(seed)}, warmRng{std::mt19937_64(seed ^ 0x9e3779b97f4a7c15ull)} {}

	// Pairs without a built answer: the same pose, one centre, or a random pose (long-double check).
	void Unbuilt(Category cat, double scale, const std::shared_ptr<SuperellipsoidShape>& a, const std::shared_ptr<SuperellipsoidShape>& b)
	{
		Tally& t = tallies[int(cat)];
		const Tally before = t;
		const Pose3 pa(scale * Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)), rng.Rotation());
		Pose3 pb = cat == Category::identicalPose ? pa : Pose3(pa.p, rng.Rotation());
		if (cat == Category::random)
			pb.p = pa.p + rng.Uniform(0.05, 2.0) * (a->BoundingRadius() + b->BoundingRadius()) * rng.Unit();
		Headline& h = CentreInside(*a, pa, *b, pb) ? beyondRange : inRange;
		ContactResult3 c;
		const bool solved = Solve(t, *a, pa, *b, pb, c);
		if (solved && cat != Category::random)
		{
			// No level point: the overlap axis, touching, the points on their surfaces.
			const bool sane = c.touching && c.separation < 0.0 && std::fabs(a->Level(ToBody(pa, c.pointA)) - 1.0) < 1e-9 &&
			                  std::fabs(b->Level(ToBody(pb, c.pointB)) - 1.0) < 1e-9;
			if (!sane)
				++t.wrongVerdict;
		}
		h.CountOutcome(before, t);
		if (!solved || cat != Category::random)
			return;
		// The long-double polish of the equations from the answer.
		const r3::Shape A(*a), B(*b);
		const r3::Pose la(pa), lb(pb);
		const r3::V3 X = r3::From(c.point);
		const r3::V3 ga = la.Rotate(A.Gradient(la.ToBody(X))), gb = lb.Rotate(B.Gradient(lb.ToBody(X)));
		r3::LD residual = 0.0L;
		const r3::SurfaceMinimum m = r3::Polish(A, la, B, lb, X, -r3::Dot(ga, gb) / r3::Dot(gb, gb), &residual);
		const double size = 0.5 * (a->BoundingRadius() + b->BoundingRadius());
		const double levelError = double(std::fabs((c.level - m.level) / m.level)), pointError = double(r3::Dist(c.point, m.point)) / size;
		if (m.level < 1e-9L)
		{
			// Centres within a hair of each other (in the levels' measure): ill-posed, apart.
			++t.flat;
			t.flatLevel = std::max(t.flatLevel, levelError);
			t.flatPoint = std::max(t.flatPoint, pointError);
			return;
		}
		const Vec3 exactNormal = r3::ToVec(r3::Unit(la.Rotate(A.Gradient(la.ToBody(m.point)))));
		Errors(t, h, levelError, pointError, Angle(c.normal, exactNormal), false, CaseJson(*a, pa, *b, pb, c));
	}

	// A pair built with a known answer, solved cold, then warm after each of kWarmSteps small
	// motions (as the Box2D adapter keeps a contact's warm start from step to step).
	void BuiltPair(Category cat, const std::shared_ptr<SuperellipsoidShape>& a, const std::shared_ptr<SuperellipsoidShape>& b)
	{
		double C = 1.0;
		if (cat == Category::built || cat == Category::identical)
			C = rng.LogUniform(1e-3, 1e3);
		else if (cat == Category::nearTangent)
			C = 1.0 + rng.Uniform(-1e-9, 1e-9);
		else
			C = rng.LogUniform(1e-6, 1e-2);
		BuildParams params = DrawBuild(rng, *a, C);
		// The cold solve records the warm start the motions below begin from.
		WarmStart3 warm;
		const Built p = Build(a, b, params);
		if (!SolveBuilt(tallies[int(cat)], inRange, beyondRange, p, warm))
			return;
		const double size = 0.5 * (p.a->BoundingRadius() + p.b->BoundingRadius());
		for (int step = 0; step < kWarmSteps; ++step)
		{
			const double delta = warmRng.LogUniform(1e-6, 1e-2);
			params = Perturb(warmRng, params, size, delta, cat == Category::nearTangent ? 1e-10 : delta);
			if (!SolveBuilt(warmTallies[int(cat)], warmInRange, warmBeyondRange, Build(a, b, params), warm))
				return;
		}
	}

	// A built pair solved (from `warm` where it is valid; the answer recorded in it) and judged
	// against its known answer, into the category's tally and the headline its centres choose.
	static bool SolveBuilt(Tally& t, Headline& range, Headline& beyond, const Built& p, WarmStart3& warm)
	{
		Headline& h = CentreInside(*p.a, p.pa, *p.b, p.pb) ? beyond : range;
		const Tally before = t;
		ContactResult3 c;
		const bool solved = Solve(t, *p.a, p.pa, *p.b, p.pb, c, &warm);
		if (solved && WrongVerdict(p, c))
		{
			++t.wrongVerdict;
			h.wrongVerdictCase = CaseWithAnswer(p, c);
		}
		h.CountOutcome(before, t);
		if (solved)
			CheckBuilt(t, h, p, c);
		return solved;
	}
};

Json TallyJson(const Tally& t)
{
	Json perMethod = Json::object();
	for (const auto& [name, n] : t.methods)
		perMethod[name] = 1e6 * t.methodSeconds.at(name) / double(n);
	return {{"configurations", t.configurations},
	        {"converged", t.converged},
	        {"converged_after_fallback", t.fallback},
	        {"failed", t.failed},
	        {"non_finite", t.nonFinite},
	        {"wrong_verdict", t.wrongVerdict},
	        {"checked", t.checked},
	        {"inaccurate_beyond_1e-9", t.inaccurate},
	        {"max_level_error", t.worstLevel},
	        {"max_point_error", t.worstPoint},
	        {"max_normal_error", t.worstNormal},
	        {"ill_conditioned", t.flat},
	        {"ill_conditioned_max_level_error", t.flatLevel},
	        {"ill_conditioned_max_point_error", t.flatPoint},
	        {"mean_contact_us", 1e6 * t.seconds / std::max(1L, t.configurations)},
	        {"answers_by_method", t.methods},
	        {"mean_us_by_method", perMethod},
	        {"worst_case", t.worstCase}};
}
} // namespace

int main(int argc, char** argv)
{
	long count = 0;
	demo::CommandLine cli("b2a_stress3d", kHelp);
	cli.Add("--count", count, 1000000, 40000, "N", "number of configurations (default 1000000, quick 40000)",
	        demo::WholeNumber(1, 1e9));
	const demo::DemoOptions opt = cli.Parse(argc, argv);
	demo::Progress progress("b2a_stress3d");
	Stress run(std::uint64_t(opt.seed));
	const auto start = std::chrono::steady_clock::now();
	for (long k = 0; k < count; ++k)
	{
		const int roll = int(k % 20);
		const Category cat = roll < 9    ? Category::built
		                     : roll < 12 ? Category::nearTangent
		                     : roll < 14 ? Category::deepOverlap
		                     : roll < 15 ? Category::identical
		                     : roll < 16 ? Category::identicalPose
		                     : roll < 17 ? Category::coincident
		                                 : Category::random;
		const double scale = run.rng.LogUniform(1e-3, 1e3);
		auto a = RandomShape(run.rng, scale);
		auto b = cat == Category::identical || cat == Category::identicalPose ? a
		                                                                      : RandomShape(run.rng, scale * run.rng.LogUniform(0.1, 10.0));
		if (cat == Category::identicalPose || cat == Category::coincident || cat == Category::random)
			run.Unbuilt(cat, scale, a, b);
		else
			run.BuiltPair(cat, a, b);
		if (k % 4096 == 0)
			progress.Report(double(k) / count, CategoryName(cat));
	}
	Json categories = Json::object(), warmCategories = Json::object();
	long bad = 0, total = 0, inaccurate = 0;
	double solveSeconds = 0.0;
	for (int i = 0; i < int(Category::count); ++i)
	{
		const Tally &t = run.tallies[i], &tw = run.warmTallies[i];
		bad += t.failed + t.nonFinite + t.wrongVerdict + tw.failed + tw.nonFinite + tw.wrongVerdict;
		total += t.configurations;
		inaccurate += t.inaccurate;
		solveSeconds += t.seconds;
		categories[CategoryName(Category(i))] = TallyJson(t);
		if (tw.configurations > 0)
			warmCategories[CategoryName(Category(i))] = TallyJson(tw);
	}
	const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	Json summary = {{"program", "b2a_stress3d"},
	                {"configurations", total},
	                {"seed", opt.seed},
	                {"in_range", run.inRange.ToJson()},
	                {"beyond_range_centre_inside", run.beyondRange.ToJson()},
	                {"warm_in_range", run.warmInRange.ToJson()},
	                {"warm_beyond_range_centre_inside", run.warmBeyondRange.ToJson()},
	                {"failed_nonfinite_or_wrong", bad},
	                {"inaccurate_beyond_1e-9", inaccurate},
	                {"errors", "level: relative; point: relative to the pair's size (mean bounding radius); normal: radians"},
	                {"categories", categories},
	                {"warm_categories", warmCategories},
	                {"solve_seconds", solveSeconds},
	                {"run_seconds", seconds},
	                {"machine", bench::MachineJson(bench::GetMachineInfo())}};
	demo::WriteJson(opt.out + "/stress3d_summary.json", summary);
	progress.Report(1.0, "done");
	const Headline& in = run.inRange;
	const Headline& warm = run.warmInRange;
	std::printf("b2a_stress3d: %ld configurations; in range %ld: %ld failed, %ld non-finite, %ld wrong verdicts, %ld wrong levels, "
	            "%ld wrong normals; warm %ld: %ld failed, %ld wrong verdicts, %ld wrong levels, %ld wrong normals; beyond range %ld: "
	            "%ld failed or wrong verdicts; %.1f us a contact; summary in %s/stress3d_summary.json\n",
	            total, in.configurations, in.failed, in.nonFinite, in.wrongVerdicts, in.wrongLevels, in.wrongNormals,
	            warm.configurations, warm.failed + warm.nonFinite, warm.wrongVerdicts, warm.wrongLevels, warm.wrongNormals,
	            run.beyondRange.configurations, run.beyondRange.failed + run.beyondRange.nonFinite + run.beyondRange.wrongVerdicts,
	            1e6 * solveSeconds / std::max(1L, total), opt.out.c_str());
	return bad == 0 && in.Clean() && warm.Clean() ? 0 : 1;
}
