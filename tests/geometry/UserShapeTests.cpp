// UserShape: shapes from an implicit function G(x, L), checked against the built-in shapes.
#include <doctest/doctest.h>

#include "GeometryReference.h"
#include "TestSupport.h"

#include <atomic>
#include <cmath>

using namespace b2a;
using namespace b2a::test;

namespace
{
double MaxAbs(Sym22 h) { return std::max({std::fabs(h.xx), std::fabs(h.xy), std::fabs(h.yy)}); }
double MaxAbsDiff(Sym22 a, Sym22 b) { return std::max({std::fabs(a.xx - b.xx), std::fabs(a.xy - b.xy), std::fabs(a.yy - b.yy)}); }
} // namespace

TEST_CASE("user shape: the heart written as G(x, L) matches the built-in HeartShape")
{
	const double alpha = 1.3;
	const auto user = MakeUserShape(UserHeartDef(alpha));
	const auto heart = MakeHeart(alpha);
	CHECK(user->Kind() == BuiltinKinds::nonConvex); // (declared neither convex nor smooth)
	CHECK(user->Describe() == "user shape 'heart'");
	CHECK(user->SurfaceLevel() == alpha);
	CHECK(!user->IsConvex());
	CHECK(!user->IsSmoothConvex());
	CHECK(!user->DerivativesCheap()); // its derivatives may be differences of its level: searches bracket
	REQUIRE(user->CornerAngles().size() == 2);
	CHECK(user->CornerAngles()[0] == -0.5 * kPi);

	Random rng(71);
	for (int i = 0; i < 300; ++i)
	{
		// Away from both axes, where ∂G/∂L = −3 cbrt(x²y³)² vanishes (see the test below).
		const double t = rng.Angle();
		const Vec2 u(std::cos(t), std::sin(t));
		if (std::fabs(u.x) < 0.1 || std::fabs(u.y) < 0.1) continue;
		const Vec2 x = rng.Uniform(0.3, 2.0) * heart->RadiusAt(u, alpha) * u;
		CAPTURE(x.x);
		CAPTURE(x.y);
		const LevelDerivatives a = user->Derivatives(x), b = heart->Derivatives(x);
		// Level: a Brent root solve to a few ulps; relative to r², the size of its terms.
		CHECK(std::fabs(a.value - b.value) <= 1e-14 * LengthSquared(x));
		// Gradient by the implicit function theorem with ∂G/∂L from a difference quotient of
		// step 1e-6 (bias h²/(3 cbrt(x²y³)²) ≲ 1e-9 here): 1e-8 relative.
		CHECK(Length(a.gradient - b.gradient) <= 1e-8 * Length(b.gradient));
		// Hessian: second differences in L with step 1e-4 carry a bias of the same form with
		// h = 1e-4 (≲ 1e-5 here): 1e-4 relative to the Hessian's size.
		CHECK(MaxAbsDiff(a.hessian, b.hessian) <= 1e-4 * MaxAbs(b.hessian));
	}
	for (int k = 0; k < 64; ++k)
	{
		const double t = -kPi + 2.0 * kPi * (k + 0.25) / 64;
		CHECK(Distance(user->SurfacePoint(t), heart->SurfacePoint(t)) <= 1e-14 * std::sqrt(alpha));
		CHECK(Distance(user->SurfacePoint(t, 0.4), heart->SurfacePoint(t, 0.4)) <= 1e-14);
	}
	// Mass and bounding radius go through the same numerical path as the built-in heart's, but
	// from a radius found by a root solve on G instead of the heart's closed-form Newton.
	CHECK(RelativeError(user->Mass().area, heart->Mass().area) < 1e-13);
	CHECK(std::fabs(user->Mass().centroid.y - heart->Mass().centroid.y) < 1e-13);
	CHECK(RelativeError(user->Mass().Ixx, heart->Mass().Ixx) < 1e-12);
	CHECK(RelativeError(user->Mass().Iyy, heart->Mass().Iyy) < 1e-12);
	CHECK(RelativeError(user->BoundingRadius(), heart->BoundingRadius()) < 1e-14);
}

TEST_CASE("user shape: derivatives stay right where dG/dL vanishes on the surface (heart axes)")
{
	// For G(x, L) = (x² + y² − L)³ − x² y³ the level L ↦ G has a triple root wherever x = 0 or
	// y = 0, so ∂G/∂L = 0 there and the implicit function theorem cannot give ∇λ. The level
	// λ = x² + y² − |x|^{2/3} y itself is smooth across y = 0 (x ≠ 0), with
	// ∇λ = (2x − (2/3) sgn(x)|x|^{−1/3} y, 2y − |x|^{2/3}) and
	// ∇²λ = [2 + (2/9)|x|^{−4/3} y, −(2/3) sgn(x)|x|^{−1/3}; ·, 2] — the HeartShape values.
	// A user shape must still report them. The same G given without derivatives (the library
	// then differentiates its level) gets them to 5e-11 (gradient) and 2e-7 (Hessian) at these
	// points; supplying the exact ∂G/∂x and ∂²G/∂x² must not make them worse than 1e-6 and 1e-4.
	UserShapeDef plain = UserHeartDef(1.0);
	plain.gradient = nullptr;
	plain.hessian = nullptr;
	const auto withDerivatives = MakeUserShape(UserHeartDef(1.0));
	const auto withoutDerivatives = MakeUserShape(plain);
	const auto heart = MakeHeart(1.0);
	for (const auto* user : {withoutDerivatives.get(), withDerivatives.get()})
	{
		INFO("G derivatives given: " << (user == withDerivatives.get()));
		for (Vec2 x : {Vec2(0.5, 0.0), Vec2(-0.7, 0.0), Vec2(1.2, 0.0), Vec2(0.5, 1e-5), Vec2(0.5, -1e-5), Vec2(-0.8, 1e-3)})
		{
			CAPTURE(x.x);
			CAPTURE(x.y);
			const LevelDerivatives a = user->Derivatives(x), b = heart->Derivatives(x);
			CHECK(RelativeError(a.value, b.value) < 1e-14);
			CHECK(Length(a.gradient - b.gradient) <= 1e-6 * Length(b.gradient));
			CHECK(MaxAbsDiff(a.hessian, b.hessian) <= 1e-4 * MaxAbs(b.hessian));
		}
		// On x = 0 λ is not differentiable in x, but ∂λ/∂y = 2y exists (λ(0, y) = y²).
		for (double y : {-0.5, 0.8})
		{
			CAPTURE(y);
			const LevelDerivatives a = user->Derivatives(Vec2(0.0, y));
			CHECK(IsFinite(a.gradient));
			CHECK(std::isfinite(a.hessian.xx + a.hessian.xy + a.hessian.yy));
			CHECK(a.gradient.y == doctest::Approx(2.0 * y).epsilon(1e-6));
		}
	}
}

TEST_CASE("user shape: an ellipse without derivatives matches the built-in ellipse")
{
	const double a = 2.0, b = 1.2;
	const auto user = MakeUserShape(UserEllipseDef(a, b));
	const auto ellipse = MakeEllipse(a, b);
	CHECK(user->SurfaceLevel() == 1.0);
	CHECK(user->IsConvex()); // declared convex
	CHECK(!user->IsSmoothConvex());
	CHECK(user->LevelPower() == 1.0);
	Random rng(72);
	for (int i = 0; i < 300; ++i)
	{
		const Vec2 p = rng.Uniform(0.2, 3.0) * ellipse->SurfacePoint(rng.Angle());
		CAPTURE(p.x);
		CAPTURE(p.y);
		const LevelDerivatives u = user->Derivatives(p), e = ellipse->Derivatives(p);
		CHECK(RelativeError(u.value, e.value) < 1e-14);
		// Central differences of the level with step 1e-6 · lengthScale: rounding ≈ 4ε λ / h.
		CHECK(Length(u.gradient - e.gradient) <= 1e-8 * (Length(e.gradient) + e.value / Length(p)));
		// Differences of those differences with step 1e-4 · lengthScale: ≈ 1e-6.
		CHECK(MaxAbsDiff(u.hessian, e.hessian) <= 1e-5 * MaxAbs(e.hessian));
	}
	for (int k = 0; k < 64; ++k)
	{
		const double t = -kPi + 2.0 * kPi * (k + 0.25) / 64;
		CHECK(Distance(user->SurfacePoint(t), ellipse->SurfacePoint(t)) <= 1e-14 * a);
		const Vec2 d = Rotate(Rot(t), Vec2(1, 0));
		// Support of a user shape: sampled, then refined; its value is exact to rounding.
		CHECK(std::fabs(Dot(user->Support(d), d) - Dot(ellipse->Support(d), d)) <= 1e-13 * a);
	}
	// Numerical mass against the closed forms πab, πab³/4, πa³b/4.
	CHECK(RelativeError(user->Mass().area, kPi * a * b) < 1e-13);
	CHECK(Length(user->Mass().centroid) < 1e-14 * a);
	CHECK(RelativeError(user->Mass().Ixx, kPi * a * b * b * b / 4) < 1e-13);
	CHECK(RelativeError(user->Mass().Iyy, kPi * a * a * a * b / 4) < 1e-13);
	CHECK(std::fabs(user->Mass().Ixy) < 1e-14 * user->Mass().polarMoment);
	CHECK(RelativeError(user->BoundingRadius(), a) < 1e-14);
}

TEST_CASE("user shape: the level solve brackets levels far from the own level")
{
	// Root solve of L ↦ G(x, L) = q(x) − L starting from L₀ = 1 by doubling steps: levels many
	// orders of magnitude away, on either side, must come out to a few ulps.
	const auto user = MakeUserShape(UserEllipseDef(2.0, 1.2));
	for (double scale : {1e-4, 1e-2, 0.5, 1.0, 3.0, 1e2, 1e4})
		for (double t : {0.1, 1.0, 2.5, -2.0})
		{
			const Vec2 p = scale * Vec2(2.0 * std::cos(t), 1.2 * std::sin(t));
			CAPTURE(scale);
			CHECK(RelativeError(user->Level(p), scale * scale) < 1e-14);
		}
	// The centre is at level 0 (G(0, L) = −L changes sign at 0).
	CHECK(std::fabs(user->Level(Vec2(0, 0))) < 1e-15);
}

TEST_CASE("user shape: levelOf replaces the root solve, and the declared flags are kept")
{
	std::atomic<int> gCalls{0}, levelCalls{0};
	UserShapeDef def = UserEllipseDef(2.0, 1.2);
	auto g = def.function;
	def.function = [&](Vec2 x, double L) { ++gCalls; return g(x, L); };
	def.levelOf = [&](Vec2 x) { ++levelCalls; return x.x * x.x / 4.0 + x.y * x.y / 1.44; };
	def.smooth = true;
	def.levelPower = 2.0;
	def.name = "fast ellipse";
	const auto user = MakeUserShape(def);
	CHECK(user->IsConvex()); // smooth implies convex
	CHECK(user->IsSmoothConvex());
	CHECK(user->LevelPower() == 2.0);
	CHECK(user->Describe() == "user shape 'fast ellipse'");
	gCalls = 0;
	levelCalls = 0;
	CHECK(user->Level(Vec2(1.0, 0.6)) == 0.25 + 0.25);
	CHECK(gCalls == 0);
	CHECK(levelCalls == 1);
	// And the shape built on levelOf is the same ellipse.
	CHECK(RelativeError(user->Mass().area, kPi * 2.0 * 1.2) < 1e-13);
	CHECK(RelativeError(user->SurfacePoint(0.7).x, MakeEllipse(2.0, 1.2)->SurfacePoint(0.7).x) < 1e-14);
}

TEST_CASE("user shape: corner angles given as any angle are kept within one half turn of zero, and NearCorner finds them across the wrap")
{
	// The heart's corners given a few turns away (and one far away): stored wrapped, as
	// CornerAngles promises, so NearCorner (which compares angles in [−π, π] without a
	// remainder) finds them.
	UserShapeDef def = UserHeartDef(1.0);
	def.cornerAngles = {0.5 * kPi + 6.0 * kPi, -0.5 * kPi - 1e6 * kPi};
	const auto user = MakeUserShape(def);
	REQUIRE(user->CornerAngles().size() == 2);
	CHECK(std::fabs(user->CornerAngles()[0] + 0.5 * kPi) <= 1e-9);
	CHECK(std::fabs(user->CornerAngles()[1] - 0.5 * kPi) <= 1e-14); // (6π + π/2 carries 6π's rounding)
	for (double c : user->CornerAngles())
	{
		CHECK(c >= -kPi);
		CHECK(c < kPi);
	}
	CHECK(user->NearCorner(0.5 * kPi + 1e-8, 1e-7));
	CHECK(!user->NearCorner(0.5 * kPi + 1e-6, 1e-7));
	CHECK(!user->NearCorner(0.0, 1e-7));
	// A corner at −π is near θ = π (the same direction).
	const auto square = MakeSuperellipse(1.0, 1.0, 2.0, 1.0); // m = 1: corners at 0 and −π
	REQUIRE(square->CornerAngles().size() == 2);
	CHECK(square->NearCorner(kPi, 1e-12));
	CHECK(square->NearCorner(kPi - 1e-13, 1e-12));
	CHECK(square->NearCorner(-kPi + 1e-13, 1e-12));
	CHECK(!square->NearCorner(0.5 * kPi, 1e-12));
}

TEST_CASE("shape: CentreLevel is the level at the body origin, computed once")
{
	// Built-in shapes are centred on their origin: level 0 there.
	CHECK(MakeHeart(1.3)->CentreLevel() == 0.0);
	CHECK(MakeSuperellipse(2.0, 1.0, 4.0, 8.0)->CentreLevel() == 0.0);
	// An ellipse centred at c = (0.5, −0.2), axes 2 and 1.2 along x and y: at the origin
	// q(0) = 0.5²/2² + 0.2²/1.2², by levelOf and by the root solve of G.
	const double expected = 0.25 / 4.0 + 0.04 / 1.44;
	for (const bool giveLevelOf : {true, false})
	{
		CAPTURE(giveLevelOf);
		const auto user = MakeUserShape(OffsetEllipseDef(2.0, 1.2, 0.0, Vec2(0.5, -0.2), giveLevelOf));
		CHECK(RelativeError(user->CentreLevel(), expected) < 1e-14);
		CHECK(user->CentreLevel() == user->Level(Vec2(0.0, 0.0)));
	}
}
