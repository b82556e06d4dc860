// Ellipse pairs against the Perram–Wertheim contact function computed in long double.
//
// Reference (ContactReference.h, PerramWertheim): with F_i(X) = (X − c_i)ᵀ M_i (X − c_i),
// S(μ) = min_X (F_A + μF_B)/(1 + μ) has the closed-form minimiser X(μ) (a 2×2 linear solve) and
// C = max_μ S(μ) is reached where F_A(X(μ)) = F_B(X(μ)), a monotone function of log μ that is
// bisected to long-double resolution. Levels are evaluated through body coordinates, so the
// reference is exact to ~1e-17 relative even for aspect 100 (checked against a second,
// unrelated long-double reference in SolverAgreementTests).
//
// Cases: random ellipses with aspect ratios 1 to 100 and sizes 1e-3 to 1e3, placed so that the
// reference common level hits chosen targets from deep overlap (0.01) through near-tangency
// (1 ± 1e-6) to far apart (1e3). For ellipses the level sets are the particle scaled by √L about
// its centre, so along a fixed direction C grows as the square of the centre distance and one
// reference solve gives the distance for any target.
//
// Tolerances (the brief's 1e-10): each solver stops at rounding level in double. The common
// level is stationary at the solution (a min–max value), so rounding of the point enters it only
// at second order; what remains is the rounding of the level evaluations, amplified by the ratio
// of the world coordinates (up to ~10 sizes from the origin) to the thinnest semi-axis (down to
// 1/100 of the size): ~1e-16 · 1e3 = 1e-13 (measured: 5e-13 at worst). The point is not
// stationary, and where the two surfaces are nearly parallel it is ill-conditioned along the
// tangent; it is checked to 1e-10 of the rescaled pair's size, the normal to 1e-10 (measured:
// below 1e-13).
#include <doctest/doctest.h>

#include <iomanip>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"
#include "ContactReference.h"

#include <vector>

using namespace b2a;
using namespace b2a::test;
using ref::LD;
using ref::V;

namespace
{
struct EllipseCase
{
	double aA, bA, aB, bB;
	Pose pa, pb;
	LD target; // the level the placement aimed at (the actual reference is recomputed)
};

ref::Quad QuadA(const EllipseCase& c) { return ref::QuadOf(c.aA, c.bA, ref::Of(c.pa)); }
ref::Quad QuadB(const EllipseCase& c) { return ref::QuadOf(c.aB, c.bB, ref::Of(c.pb)); }

// Random ellipse pairs placed at chosen reference levels.
// Aspect ratios log-uniform from 1 to maxAspect; circleB: B is a circle of A's size scale.
std::vector<EllipseCase> Cases(std::uint64_t seed, int pairs, const std::vector<LD>& targets, double maxAspect = 100.0,
                               bool circleB = false)
{
	Random rng(seed);
	std::vector<EllipseCase> out;
	for (int k = 0; k < pairs; ++k)
	{
		const double size = rng.LogUniform(1e-3, 1e3);
		auto axes = [&](double& a, double& b) {
			const double major = size * rng.LogUniform(0.5, 2.0), aspect = rng.LogUniform(1.0, maxAspect);
			a = major;
			b = major / aspect;
			if (rng.Uniform(0.0, 1.0) < 0.5) std::swap(a, b);
		};
		EllipseCase c{};
		axes(c.aA, c.bA);
		axes(c.aB, c.bB);
		if (circleB)
			c.bB = c.aB;
		const Vec2 ca(rng.Uniform(-10.0, 10.0) * size, rng.Uniform(-10.0, 10.0) * size);
		const double thA = rng.Angle(), thB = rng.Angle(), dir = rng.Angle();
		const Vec2 u(std::cos(dir), std::sin(dir));
		// Tangency distance along u from one reference solve at distance `size`.
		c.pa = Pose(ca, thA);
		c.pb = Pose(ca + size * u, thB);
		const LD C0 = ref::PerramWertheim(QuadA(c), QuadB(c)).level;
		const LD tangent = LD(size) / std::sqrt(C0);
		for (LD t : targets)
		{
			EllipseCase e = c;
			e.pb = Pose(ca + double(tangent * std::sqrt(t)) * u, thB);
			e.target = t;
			out.push_back(e);
		}
	}
	return out;
}

const std::vector<LD> kTargets = {0.01L, 0.3L, 0.9L, 1.0L - 1e-6L, 1.0L + 1e-6L, 1.5L, 10.0L, 1e3L};

double LevelErr(double got, LD want) { return double(std::fabs(LD(got) - want) / want); }
} // namespace

TEST_CASE("ellipses: every common-level solver matches the long-double Perram-Wertheim reference")
{
	const auto cases = Cases(7001, 14, kTargets);
	for (const EllipseCase& c : cases)
	{
		const auto a = MakeEllipse(c.aA, c.bA), b = MakeEllipse(c.aB, c.bB);
		const ref::PwResult want = ref::PerramWertheim(QuadA(c), QuadB(c));
		// Length scale of the touching point: the rescaled particles' sizes.
		const LD scale = std::sqrt(want.level) * (std::max(c.aA, c.bA) + std::max(c.aB, c.bB));
		INFO("A=(" << c.aA << "," << c.bA << ") B=(" << c.aB << "," << c.bB << ") C_ref=" << double(want.level));
		const std::pair<const char*, LevelResult> results[] = {
			{"SolveCommonLevelNewton", SolveCommonLevelNewton(*a, c.pa, *b, c.pb)},
			{"SolveCommonLevelMinMax", SolveCommonLevelMinMax(*a, c.pa, *b, c.pb)},
			{"SolveCommonLevelGrid", SolveCommonLevelGrid(*a, c.pa, *b, c.pb)},
			{"SolveCommonLevel", SolveCommonLevel(*a, c.pa, *b, c.pb)},
		};
		for (const auto& item : results)
		{
			const auto& name = item.first;
			const auto& r = item.second;
			INFO(std::string(name));
			REQUIRE(r.Ok());
			const double le = LevelErr(r.level, want.level);
			const double pe = double(ref::Dist(r.point, want.point) / scale);
			CHECK(le <= 1e-10);
			CHECK(pe <= 1e-10);
			CHECK(double(ref::Dist(r.normal, want.normal)) <= 1e-10);
		}
	}
}

TEST_CASE("ellipses: ComputeContact's points, normal and separation match the long-double line-ellipse intersections")
{
	// Reference: the PW point and normal, and the roots of F(X + s·n) = 1 on each ellipse (the
	// side the line leaves or first enters, as ContactResult documents), or where the line misses
	// a particle the documented radial point c + (X − c)/√F(X). Separation to 1e-9 of the size:
	// it is a difference of two such points, each as exact as the common point (see above).
	const auto cases = Cases(7002, 10, {0.05L, 0.5L, 0.99L, 1.01L, 2.0L, 5.0L});
	int compared = 0, fallbacks = 0;
	for (const EllipseCase& c : cases)
	{
		const auto a = MakeEllipse(c.aA, c.bA), b = MakeEllipse(c.aB, c.bB);
		const ref::EllipseContactRef want = ref::EllipseContact(QuadA(c), QuadB(c));
		++compared;
		fallbacks += !want.lineHitsBoth;
		const LD size = std::max(c.aA, c.bA) + std::max(c.aB, c.bB);
		INFO("A=(" << c.aA << "," << c.bA << ") B=(" << c.aB << "," << c.bB << ") C_ref=" << double(want.level.level));
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::newton})
		{
			const ContactResult r = ComputeContact(*a, c.pa, *b, c.pb, m);
			REQUIRE(r.Ok());
			const double e1 = double(ref::Dist(r.normal, want.level.normal));
			const double e2 = double(ref::Dist(r.pointA, want.pointA) / size);
			const double e3 = double(ref::Dist(r.pointB, want.pointB) / size);
			const double e4 = double(std::fabs(LD(r.separation) - want.separation) / size);
			CHECK(e1 <= 1e-9);
			CHECK(e2 <= 1e-9);
			CHECK(e3 <= 1e-9);
			CHECK(e4 <= 1e-9);
			CHECK(r.touching == (want.level.level <= 1.0L));
			CHECK(r.touching == (want.separation <= 0.0L));
		}
	}
	CHECK(compared == 60);
	CHECK(fallbacks < compared / 2); // the fallback is the exception (far-apart, thin pairs)
}

TEST_CASE("ellipses: the one-sided scale (grid and Newton) matches the long-double Lagrange point")
{
	// Reference: the Lagrange point X(μ), μ > 0, on B's surface (EllipseScaleRef), exact for A's
	// centre outside B. Same tolerances as the common level: the scale is a minimum (stationary).
	const auto cases = Cases(7003, 10, {1.5L, 4.0L, 30.0L});
	for (const EllipseCase& c : cases)
	{
		const auto a = MakeEllipse(c.aA, c.bA), b = MakeEllipse(c.aB, c.bB);
		if (QuadB(c).F(ref::FromVec(c.pa.p)) <= 1.0L)
			continue; // A's centre inside B
		const ref::PwResult want = ref::EllipseScaleRef(QuadA(c), QuadB(c));
		const LD scale = std::max(c.aB, c.bB) + std::sqrt(want.level) * std::max(c.aA, c.bA);
		INFO("A=(" << c.aA << "," << c.bA << ") B=(" << c.aB << "," << c.bB << ") scale_ref=" << double(want.level));
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::grid, MethodChoice::newton})
		{
			const LevelResult r = SolveScaleA(*a, c.pa, *b, c.pb, m);
			INFO("method " << int(m) << ": " << std::string(r.failure) << " pa=(" << std::setprecision(17) << c.pa.p.x << "," << c.pa.p.y << "," << c.pa.q.Angle() << ") pb=(" << c.pb.p.x << "," << c.pb.p.y << "," << c.pb.q.Angle() << ")");
			REQUIRE(r.Ok());
			const double le = LevelErr(r.level, want.level), pe = double(ref::Dist(r.point, want.point) / scale);
			CHECK(le <= 1e-10);
			CHECK(pe <= 1e-9);
		}
	}
}

TEST_CASE("ellipses: two ellipses take the Perram-Wertheim solver, exact to the reference up to aspect 1000, warm or cold")
{
	// SolveCommonLevel's automatic choice for two plain ellipses is Newton on the one-dimensional
	// Perram–Wertheim form (EllipsePairLevel.cpp): 2×2 algebra, no shape evaluation. The pairs
	// here reach aspect 1000 (the generic Newton fails on most such needles and falls back);
	// level, point and normal are checked against the long-double reference and the multiplier
	// against its μ; a warm start from a pose moved by 1e-3 of the size takes at most 5 steps
	// (3 for most; each a pair of 2×2 solves).
	Random rng(8101);
	int cases = 0;
	double worstLevel = 0.0, worstPoint = 0.0, worstNormal = 0.0;
	for (int k = 0; k < 60; ++k)
	{
		const double size = rng.LogUniform(1e-3, 1e3);
		double axes[4];
		for (int i = 0; i < 2; ++i)
		{
			const double major = size * rng.LogUniform(0.5, 2.0), aspect = rng.LogUniform(1.0, 1000.0);
			axes[2 * i] = major;
			axes[2 * i + 1] = major / aspect;
		}
		const auto a = MakeEllipse(axes[0], axes[1]), b = MakeEllipse(axes[2], axes[3]);
		const Vec2 ca(rng.Uniform(-10.0, 10.0) * size, rng.Uniform(-10.0, 10.0) * size);
		const double dir = rng.Angle(), thA = rng.Angle(), thB = rng.Angle();
		const Vec2 u(std::cos(dir), std::sin(dir));
		const Pose pa(ca, thA);
		const ref::PwResult at1 = ref::PerramWertheim(ref::QuadOf(axes[0], axes[1], ref::Of(pa)),
		                                              ref::QuadOf(axes[2], axes[3], ref::Of(Pose(ca + size * u, thB))));
		const double tangent = size / double(std::sqrt(at1.level));
		for (double t : {0.05, 0.9, 1.0 - 1e-7, 1.0 + 1e-7, 1.3, 50.0})
		{
			const Pose pb(ca + tangent * std::sqrt(t) * u, thB);
			const ref::PwResult want =
				ref::PerramWertheim(ref::QuadOf(axes[0], axes[1], ref::Of(pa)), ref::QuadOf(axes[2], axes[3], ref::Of(pb)));
			const LD scale = std::sqrt(want.level) * (std::max(axes[0], axes[1]) + std::max(axes[2], axes[3]));
			INFO("A=(" << axes[0] << "," << axes[1] << ") B=(" << axes[2] << "," << axes[3] << ") C_ref=" << double(want.level));
			WarmStart warm;
			const LevelResult cold = SolveCommonLevel(*a, pa, *b, pb, MethodChoice::automatic, {}, &warm);
			REQUIRE(cold.Ok());
			CHECK(cold.method == SolveMethod::ellipsePair);
			CHECK(cold.status == SolveStatus::converged);
			worstLevel = std::max(worstLevel, LevelErr(cold.level, want.level));
			worstPoint = std::max(worstPoint, double(ref::Dist(cold.point, want.point) / scale));
			worstNormal = std::max(worstNormal, double(ref::Dist(cold.normal, want.normal)));
			CHECK(double(std::fabs(LD(cold.multiplier) - want.mu) / want.mu) <= 1e-8);
			// A small motion, then the warm start.
			const Pose moved(pb.p + 1e-3 * size * Vec2(0.6, -0.8), thB + 1e-3);
			const LevelResult again = SolveCommonLevel(*a, pa, *b, moved, MethodChoice::automatic, {}, &warm);
			const ref::PwResult want2 =
				ref::PerramWertheim(ref::QuadOf(axes[0], axes[1], ref::Of(pa)), ref::QuadOf(axes[2], axes[3], ref::Of(moved)));
			REQUIRE(again.Ok());
			CHECK(again.method == SolveMethod::ellipsePair);
			CHECK(again.iterations <= 5);
			worstLevel = std::max(worstLevel, LevelErr(again.level, want2.level));
			++cases;
		}
	}
	CAPTURE(worstLevel);
	CAPTURE(worstPoint);
	CAPTURE(worstNormal);
	CHECK(cases == 360);
	CHECK(worstLevel <= 1e-12); // measured 2.2e-14 (1.1e-14 before 2026-12-05's steps), point 3e-15, normal 9e-14
	CHECK(worstPoint <= 1e-12);
	CHECK(worstNormal <= 1e-12);
}

namespace
{
// The normal's, the points' (over `size`) and the separation's (over `size`) errors against the
// reference, each checked to `tolerance`; returns the largest.
double CheckContactErrors(const ContactResult& r, const ref::EllipseContactRef& want, LD size, double tolerance)
{
	const double errors[] = {double(ref::Dist(r.normal, want.level.normal)), double(ref::Dist(r.pointA, want.pointA) / size),
	                         double(ref::Dist(r.pointB, want.pointB) / size),
	                         double(std::fabs(LD(r.separation) - want.separation) / size)};
	double worst = 0.0;
	for (double e : errors)
	{
		CHECK(e <= tolerance);
		worst = std::max(worst, e);
	}
	return worst;
}
} // namespace

TEST_CASE("ellipses: EllipseContact serves ellipse and circle pairs, points to 1e-12 of the reference, warm mostly in two steps")
{
	// The dispatch table's entry for two plain ellipses (or an ellipse and a circle) solves
	// Perram–Wertheim by Halley steps and, up to aspect 16, takes the points from the quadratics
	// along the normal in the world frame (no body-frame line search). Checked against the
	// long-double line-ellipse reference, cold and after a motion of 1e-3 of the size: a warm
	// start 1e-3 off is at ~1e-9 after one Halley step, so the second is the last (measured:
	// worst error 4.5e-15; 3.5e-15 before the Halley steps stopped waiting for 1/det).
	CHECK((GetContactFunction(BuiltinKinds::ellipse, BuiltinKinds::ellipse) == &EllipseContact));
	CHECK((GetContactFunction(BuiltinKinds::ellipse, BuiltinKinds::circle) == &EllipseContact));
	CHECK((GetContactFunction(BuiltinKinds::circle, BuiltinKinds::ellipse) == &EllipseContact));
	const std::vector<LD> targets = {0.05L, 0.5L, 0.99L, 1.0L - 1e-6L, 1.0L + 1e-6L, 1.01L, 2.0L, 5.0L};
	std::vector<EllipseCase> cases = Cases(7004, 16, targets, 4.0);
	for (const EllipseCase& c : Cases(7005, 8, targets, 4.0, true))
		cases.push_back(c);
	double worst = 0.0;
	int warmSteps = 0, warmTotal = 0, warmCount = 0, compared = 0;
	for (size_t k = 0; k < cases.size(); ++k)
	{
		const EllipseCase& c = cases[k];
		// Every third A in the normalised form with ζ = 1 (the same ellipse, level f^1).
		const ShapePtr a = k % 3 == 0 ? ShapePtr(SuperellipseShape::FromZeta(c.aA, c.bA, 1.0)) : ShapePtr(MakeEllipse(c.aA, c.bA));
		const ShapePtr b = MakeEllipse(c.aB, c.bB);
		INFO("case " << k << ": A=(" << c.aA << "," << c.bA << ") B=(" << c.aB << "," << c.bB << ") target " << double(c.target));
		const LD size = std::max(c.aA, c.bA) + std::max(c.aB, c.bB);
		WarmStart warm;
		const Pose moved(c.pb.p + 1e-3 * double(size) * Vec2(0.6, -0.8), c.pb.q.Angle() + 1e-3);
		for (const Pose& pb : {c.pb, moved})
		{
			EllipseCase at = c;
			at.pb = pb;
			const ref::EllipseContactRef want = ref::EllipseContact(QuadA(at), QuadB(at));
			const ContactResult r = EllipseContact(*a, c.pa, *b, pb, {}, &warm);
			REQUIRE(r.Ok());
			CHECK(r.method == SolveMethod::ellipsePair);
			CHECK(warm.valid);
			worst = std::max(worst, CheckContactErrors(r, want, size, 1e-12));
			CHECK(r.touching == (want.separation <= 0.0L));
			// The dispatch table calls it: the same answer from the same (cold) start.
			const ContactResult cold = EllipseContact(*a, c.pa, *b, pb, {}, nullptr);
			const ContactResult viaTable = ComputeContact(*a, c.pa, *b, pb);
			CHECK(viaTable.pointA.x == cold.pointA.x);
			CHECK(viaTable.pointB.y == cold.pointB.y);
			CHECK(viaTable.separation == cold.separation);
			if (pb.p.x == moved.p.x)
			{
				warmSteps = std::max(warmSteps, r.iterations);
				warmTotal += r.iterations;
				++warmCount;
			}
			++compared;
		}
	}
	CAPTURE(worst);
	CAPTURE(warmSteps);
	CAPTURE(warmTotal);
	CAPTURE(warmCount);
	CHECK(compared == 2 * 24 * 8);
	CHECK(worst > 0.0);
	CHECK(warmSteps <= 3);                      // measured: 3 in 2 of 192 cases
	CHECK(warmTotal <= 2.05 * warmCount);       // measured: 386 steps in 192 (Newton took ~2.5)
}

TEST_CASE("ellipses: EllipseContact up to aspect 100, a line that misses by the radial point, to 1e-10 of the reference")
{
	// Up to aspect 16 the Perram–Wertheim point is finished in double (the level matrix's
	// condition is at most 256), beyond after a refining step; where the normal line misses a particle
	// (most separated pairs beyond aspect 10) its point is the radial one in closed form. Both
	// against the long-double reference: points, normal and separation to 1e-10 of the size
	// (measured: 1.5e-14, 3.1e-14 before 2026-12-05; 71 of the 168 lines miss one particle).
	const std::vector<LD> targets = {0.05L, 0.5L, 0.99L, 1.01L, 2.0L, 5.0L, 30.0L};
	const std::vector<EllipseCase> cases = Cases(7006, 24, targets, 100.0);
	double worst = 0.0;
	int misses = 0;
	for (const EllipseCase& c : cases)
	{
		const auto a = MakeEllipse(c.aA, c.bA), b = MakeEllipse(c.aB, c.bB);
		INFO("A=(" << c.aA << "," << c.bA << ") B=(" << c.aB << "," << c.bB << ") target " << double(c.target));
		const ref::EllipseContactRef want = ref::EllipseContact(QuadA(c), QuadB(c));
		misses += !want.lineHitsBoth;
		const LD size = std::max(c.aA, c.bA) + std::max(c.aB, c.bB);
		const ContactResult r = EllipseContact(*a, c.pa, *b, c.pb, {}, nullptr);
		REQUIRE(r.Ok());
		CHECK(r.method == SolveMethod::ellipsePair);
		worst = std::max(worst, CheckContactErrors(r, want, size, 1e-10));
		CHECK(r.touching == (want.separation <= 0.0L));
	}
	CAPTURE(worst);
	CAPTURE(misses);
	CHECK(misses >= 10);
	CHECK(worst > 0.0);
	MESSAGE("worst " << worst << ", misses " << misses << " of " << cases.size());
}

namespace
{
// Two random needles (aspect minAspect to 1000, sizes 1e-2 to 1e2) and, along a random direction,
// the centre distance at which their common level is 1 (a pose of B at distance d·√t has level t).
struct NeedlePair
{
	double size, aA, bA, aB, bB;
	std::shared_ptr<SuperellipseShape> a, b;
	Pose pa;
	Vec2 u;
	double thB;     // B's angle
	double tangent; // the centre distance at level 1
	ref::Quad qa;

	NeedlePair(Random& rng, double minAspect, bool halfParallel, int k)
	{
		size = rng.LogUniform(1e-2, 1e2);
		aA = size * rng.LogUniform(0.5, 2.0);
		aB = size * rng.LogUniform(0.5, 2.0);
		bA = aA / rng.LogUniform(minAspect, 1000.0);
		bB = aB / rng.LogUniform(minAspect, 1000.0);
		a = MakeEllipse(aA, bA);
		b = MakeEllipse(aB, bB);
		pa = Pose(Vec2(rng.Uniform(-5.0, 5.0) * size, rng.Uniform(-5.0, 5.0) * size), rng.Angle());
		const double dir = rng.Angle();
		u = Vec2(std::cos(dir), std::sin(dir));
		thB = halfParallel && k % 2 ? pa.q.Angle() + rng.Uniform(-0.01, 0.01) : rng.Angle();
		qa = ref::QuadOf(aA, bA, ref::Of(pa));
		const ref::PwResult at1 = ref::PerramWertheim(qa, ref::QuadOf(aB, bB, ref::Of(Pose(pa.p + size * u, thB))));
		tangent = size / double(std::sqrt(at1.level));
	}
	/// B at distance tangent·factor along u, and the reference there.
	Pose B(double factor) const { return Pose(pa.p + tangent * factor * u, thB); }
	ref::PwResult Want(const Pose& pb) const { return ref::PerramWertheim(qa, ref::QuadOf(aB, bB, ref::Of(pb))); }
};

// The worst level and point errors and the Halley steps of Perram–Wertheim solves.
struct SolveTally
{
	int solves = 0, worstSteps = 0, totalSteps = 0;
	double worstLevel = 0.0, worstPoint = 0.0;

	void Add(const LevelResult& r, const ref::PwResult& want, LD scale)
	{
		REQUIRE(r.Ok());
		REQUIRE(r.method == SolveMethod::ellipsePair);
		worstLevel = std::max(worstLevel, LevelErr(r.level, want.level));
		worstPoint = std::max(worstPoint, double(ref::Dist(r.point, want.point) / scale));
		worstSteps = std::max(worstSteps, r.iterations);
		totalSteps += r.iterations;
		++solves;
	}
	/// Checks the errors against 1e-12 and the steps against their bounds.
	void Check(int expectedSolves, int maxSteps, double meanSteps) const
	{
		CAPTURE(worstLevel);
		CAPTURE(worstPoint);
		CAPTURE(worstSteps);
		CAPTURE(totalSteps);
		CHECK(solves == expectedSolves);
		CHECK(worstLevel <= 1e-12);
		CHECK(worstPoint <= 1e-12);
		CHECK(worstSteps <= maxSteps);
		CHECK(totalSteps <= meanSteps * solves);
	}
};
} // namespace

TEST_CASE("ellipses: a warm start far from the root, as when the contact runs along needles, converges in few steps")
{
	// Between 1000:1 needles one step's turn by 1e-3 rad can move the contact from near one
	// tip to the middle, and the multiplier s/(1 − s) by a factor 1e3 or more (b2a_bench_pairs'
	// motions). Here every pair, half of them nearly parallel, is solved from warm multipliers
	// 1e-4 to 1e4 times its own: the answer is still the reference's to 1e-12, through the
	// refining steps that replaced the long-double finish, and far from the root the steps
	// are Halley's on the quartic h·det(H)² (EllipsePairLevel.cpp), where those on h alone
	// crawled (measured: at most 12 steps, 5.4 on average; on h alone up to 23, 8.4).
	Random rng(4242);
	SolveTally tally;
	for (int k = 0; k < 40; ++k)
	{
		const NeedlePair n(rng, 100.0, true, k); // half of them near parallel
		const auto &a = n.a, &b = n.b;
		const Pose& pa = n.pa;
		const Pose pb = n.B(rng.Uniform(0.8, 1.2));
		const ref::PwResult want = n.Want(pb);
		const LD scale = std::sqrt(want.level) * (n.aA + n.aB);
		for (double factor : {1e-4, 1e-2, 0.1, 10.0, 1e2, 1e4})
		{
			INFO("A=(" << n.aA << "," << n.bA << ") B=(" << n.aB << "," << n.bB << ") mu " << double(want.mu) << " warm x" << factor);
			WarmStart warm;
			warm.valid = true;
			warm.multiplier = double(want.mu) * factor;
			tally.Add(SolveCommonLevel(*a, pa, *b, pb, MethodChoice::automatic, {}, &warm), want, scale);
		}
	}
	tally.Check(240, 14, 6.0);
}

TEST_CASE("ellipses: a cold start between needles takes the best of five support normals: few steps, exact answers")
{
	// Crossing needles meet tip to side, with the normal along the side's axis, and their
	// multiplier is hB/hA there (h the support function along the normal): two or three decades
	// from the circles' answer along the centre line that rounder pairs start from. Cold solves
	// between needles of aspect 30 to 1000 at levels from deep overlap to far apart must take few
	// Halley steps (measured: 2.8 on average, at most 4; from the centre line 5.2 and 8) and
	// match the long-double reference.
	Random rng(9191);
	SolveTally tally;
	for (int k = 0; k < 60; ++k)
	{
		const NeedlePair n(rng, 30.0, false, k);
		for (double t : {0.2, 1.0 + 1e-6, 4.0})
		{
			const Pose pb = n.B(std::sqrt(t));
			const ref::PwResult want = n.Want(pb);
			const LD scale = std::sqrt(want.level) * (n.aA + n.aB);
			INFO("A=(" << n.aA << "," << n.bA << ") B=(" << n.aB << "," << n.bB << ") mu " << double(want.mu));
			tally.Add(SolveCommonLevel(*n.a, n.pa, *n.b, pb, MethodChoice::automatic, {}), want, scale);
		}
	}
	tally.Check(180, 6, 3.5);
}

TEST_CASE("ellipses: the Perram-Wertheim solver is exact at any size, from 1e-15 to 1e15, cold and warm")
{
	// Its Halley loop carries h, h' and h'' multiplied by up to the sixth power of det(H) (to
	// spare a division per step), which scales as size⁻⁴; beyond det 1e±20 it rescales by a
	// power of two. The same pairs at sizes 1e-15 to 1e15 (det up to 1e±62, aspect up to 100) must
	// give the reference's level, point and multiplier (measured: every size within 5e-15 of the
	// reference, like size 1; without the rescaling the first pair at 1e-15 is not solved).
	const auto cases = Cases(7313, 10, {0.3L, 1.0L + 1e-6L, 10.0L});
	double worst = 0.0;
	int solves = 0;
	for (double size : {1e-15, 1e-6, 1.0, 1e6, 1e15})
		for (const EllipseCase& base : cases)
		{
			EllipseCase c = base;
			for (double* v : {&c.aA, &c.bA, &c.aB, &c.bB})
				*v *= size;
			c.pa = Pose(size * base.pa.p, base.pa.q.Angle());
			c.pb = Pose(size * base.pb.p, base.pb.q.Angle());
			const auto a = MakeEllipse(c.aA, c.bA), b = MakeEllipse(c.aB, c.bB);
			const ref::PwResult want = ref::PerramWertheim(QuadA(c), QuadB(c));
			const LD scale = std::sqrt(want.level) * (std::max(c.aA, c.bA) + std::max(c.aB, c.bB));
			INFO("size " << size << " A=(" << c.aA << "," << c.bA << ") B=(" << c.aB << "," << c.bB << ") C_ref=" << double(want.level));
			WarmStart warm;
			for (int pass = 0; pass < 2; ++pass) // cold, then warm from its own answer
			{
				const LevelResult r = SolveCommonLevel(*a, c.pa, *b, c.pb, MethodChoice::automatic, {}, &warm);
				REQUIRE(r.Ok());
				REQUIRE(r.method == SolveMethod::ellipsePair);
				worst = std::max({worst, LevelErr(r.level, want.level), double(ref::Dist(r.point, want.point) / scale),
				                  double(std::fabs(LD(r.multiplier) - want.mu) / want.mu)});
				++solves;
			}
		}
	CAPTURE(worst);
	CHECK(solves == 300);
	CHECK(worst <= 1e-12);
}

TEST_CASE("ellipses: 1000:1 needles crossing near both centres: the contact and the reference's normal match a 60-digit solution")
{
	// A cold pose of b2a_bench_pairs (ellipse_a1000, seed 1) whose long-double reference was once
	// wrong: the needles cross nearly at right angles, their centres 4e-5 apart (common level
	// 5.5e-12). There the gradients at the common point turn with the point's rounding by up to
	// (a/b)², so the bench's reference, the mean of the two unit normals there, was 5.5e-11 off,
	// and the point where the normal line leaves B, 3 units on at 0.005 rad to B's axis, 1.7e-9
	// of the size off; the library's answer is within 1e-15 (PwNormal explains the fix). The values: Newton on (∇F_A + μ∇F_B, F_A − F_B) in 60-digit
	// arithmetic (mpmath) from these exact doubles, the points the line's crossings as
	// ContactFromLevel takes them.
	const Pose pa = PoseOf(Vec2(-0x1.629b7678535ap-4, 0x1.cddce69245f2p-3), 0x1.1ef6617800b28p-2, 0x1.eb7c10b91080ap-1);
	const Pose pb = PoseOf(Vec2(-0x1.62c6fc1826639p-4, 0x1.cdd8e77df6adcp-3), 0x1.ec47cc54fb893p-1, -0x1.1973f77d5b06p-2);
	const auto a = MakeEllipse(20.0, 0.02), b = MakeEllipse(16.0, 0.016);
	const V normal{-0.9600524047640900086885497L, 0.2798202639314885000319824L};
	const V pointA{-0.1057803429717933890034608L, 0.2310974098390590409796342L};
	const V pointB{2.832419798180406214131969L, -0.625280778373253628758384L};
	const LD level = 5.541307750332651260251592e-12L;
	const double size = 18.0; // the mean bounding radius

	const ContactResult c = ComputeContact(*a, pa, *b, pb);
	REQUIRE(c.Ok());
	CHECK(LevelErr(c.level, level) <= 1e-10);
	CHECK(double(ref::Dist(c.normal, normal)) <= 1e-14);
	CHECK(double(ref::Dist(c.pointA, pointA)) <= 1e-13 * size);
	CHECK(double(ref::Dist(c.pointB, pointB)) <= 1e-13 * size);

	// The reference's normal from the shapes' matrices (PwNormal), and its points from it.
	const ref::PwResult want = ref::PerramWertheim(ref::QuadOf(LD(20.0), LD(0.02), ref::Of(pa)), ref::QuadOf(LD(16.0), LD(0.016), ref::Of(pb)));
	CHECK(double(ref::Dist(ref::ToVec(want.normal), normal)) <= 1e-14);
	CHECK(LevelErr(double(want.level), level) <= 1e-10);
}
