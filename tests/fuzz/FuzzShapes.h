// b2analytic fuzzing: shapes and poses from fuzzer bytes, and the checks every target shares.
#pragma once

#include "FuzzInput.h"

#include "b2analytic/b2analytic.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace b2a::fuzz
{

/// What the current input decoded to, printed when a check fails (a crash report then says which
/// shapes and poses to put in the regression test).
inline std::string& Context()
{
	static std::string context;
	return context;
}

/// With B2A_FUZZ_TRACE set in the environment, print how long each named step took (to find which
/// call a slow input spends its time in); the steps "shape" and "decoded" also print what was
/// decoded so far.
inline void Trace(const char* step)
{
	static const bool on = std::getenv("B2A_FUZZ_TRACE") != nullptr;
	static auto last = std::chrono::steady_clock::now();
	if (!on)
		return;
	const auto now = std::chrono::steady_clock::now();
	std::fprintf(stderr, "%10.3f ms  %s\n", std::chrono::duration<double, std::milli>(now - last).count(), step);
	if (std::string(step) == "decoded" || std::string(step) == "shape")
		std::fprintf(stderr, "input: %s\n", Context().c_str());
	last = std::chrono::steady_clock::now();
}

/// Stop the fuzzer with a message when a promise of the API is broken.
[[noreturn]] inline void Fail(const char* what, const char* file, int line)
{
	std::fprintf(stderr, "b2a fuzz check failed: %s (%s:%d)\ninput: %s\n", what, file, line, Context().c_str());
	__builtin_trap();
}

/// Check a promise of the API; on failure print it and the decoded input, then trap.
#define B2A_FUZZ_CHECK(condition) ((condition) ? (void)0 : ::b2a::fuzz::Fail(#condition, __FILE__, __LINE__))

/// Both components are not NaN (infinities allowed).
inline bool NotNaN(Vec2 v) { return !std::isnan(v.x) && !std::isnan(v.y); }

/// The pose as text, exact to the last bit.
inline std::string Describe(const Pose& p)
{
	return "Pose({" + FormatNumber(p.p.x) + ", " + FormatNumber(p.p.y) + "}, Rot{" + FormatNumber(p.q.c) + ", " +
	       FormatNumber(p.q.s) + "})";
}

/// Whether the star r(θ) = 1 + e·cos(kθ + φ) bounds a convex region: its curvature's sign is that
/// of r² + 2r'² − r·r'' (the polar curvature formula), checked at 720 angles of u = kθ + φ.
inline bool StarIsConvex(double e, int k)
{
	for (int i = 0; i < 720; ++i)
	{
		const double u = 2.0 * kPi * i / 720.0;
		const double r = 1.0 + e * std::cos(u), dr = -e * k * std::sin(u), ddr = -e * k * k * std::cos(u);
		if (r * r + 2.0 * dr * dr - r * ddr < 0.0)
			return false;
	}
	return true;
}

/// A star-shaped user shape: G(x, L) = (|x| / (s·R(θ)))^p − L with R(θ) = 1 + e·cos(kθ + φ), e < 1.
/// Its declared flags (convex, smooth) come from the bytes and may be wrong on purpose: a wrong
/// declaration may give wrong answers, but never a crash, a hang or a non-finite "converged" one.
/// Its size s and length scale stay ordinary: a user function for a particle 1e-300 wide (or
/// negative s) makes every level a thousand-step root search, and construction took seconds
/// (reported, not a crash); the level L₀ and the corner angle may be extreme (the constructor
/// checks them).
inline ShapePtr DecodeUserShape(FuzzInput& in)
{
	const double s = in.LogUniform(0.05, 20.0);
	const double e = in.Uniform(0.0, 0.9);
	const int k = in.Int(1, 8);
	const double phi = in.Uniform(-kPi, kPi);
	const double p = double(in.Int(1, 4));
	UserShapeDef def;
	def.name = "fuzz star";
	def.level = in.Number(0.2, 5.0);
	auto ratio = [=](Vec2 x) {
		const double R = s * (1.0 + e * std::cos(k * std::atan2(x.y, x.x) + phi));
		return Length(x) / R;
	};
	auto level = [=](Vec2 x) { return std::pow(ratio(x), p); };
	def.function = [=](Vec2 x, double L) { return level(x) - L; };
	if (in.Bool())
		def.levelOf = level;
	if (in.Bool())
	{
		// ∂G/∂x = p·ρ^(p−1)·∇ρ, ρ = r/R(θ): ∇ρ = x/(rR) − r·R'(θ)/R²·∇θ, ∇θ = (−y, x)/r².
		def.gradient = [=](Vec2 x, double) {
			const double r = Length(x);
			if (!(r > 0.0))
				return Vec2();
			const double t = std::atan2(x.y, x.x);
			const double R = s * (1.0 + e * std::cos(k * t + phi));
			const double dR = -s * e * k * std::sin(k * t + phi);
			const Vec2 gradRho = x / (r * R) - (r * dR / (R * R)) * (Perp(x) / (r * r));
			return p * std::pow(r / R, p - 1.0) * gradRho;
		};
	}
	def.convex = in.Bool();
	if (def.convex && !StarIsConvex(e, k))
		in.MarkExtreme();
	def.smooth = in.Bool();
	def.levelPower = in.Bool() ? 1.0 : 0.5 * p;
	def.lengthScale = in.Bool() ? s : in.LogUniform(0.05, 20.0);
	if (in.Bool())
		def.cornerAngles.push_back(in.Number(-kPi, kPi));
	// Without levelOf every level is a root search in L, and the non-convex paths march along
	// lines in hundreds of steps of those: a contact took 2 to 10 s (reported). Non-convex user
	// shapes get their level function, so that the fuzzer measures robustness, not patience.
	if (!def.levelOf && !def.convex && !def.smooth)
		def.levelOf = level;
	Context() += "user(s=" + FormatNumber(s) + " e=" + FormatNumber(e) + " k=" + std::to_string(k) + " phi=" +
	             FormatNumber(phi) + " p=" + FormatNumber(p) + " level=" + FormatNumber(def.level) +
	             (def.levelOf ? " levelOf" : "") + (def.gradient ? " gradient" : "") + (def.convex ? " convex" : "") +
	             (def.smooth ? " smooth" : "") + " levelPower=" + FormatNumber(def.levelPower) + " lengthScale=" +
	             FormatNumber(def.lengthScale) + (def.cornerAngles.empty() ? "" : " corner=" + FormatNumber(def.cornerAngles[0])) + ") ";
	return MakeUserShape(std::move(def));
}

/// A shape from the bytes: circle, ellipse, superellipse (integer or real exponents, or the
/// normalised ζ-form), heart or user shape, with lengths mostly in [minSize, maxSize].
/// Throws InvalidParameter for parameters the constructors reject (the caller catches it).
inline ShapePtr DecodeShape(FuzzInput& in, double minSize = 0.05, double maxSize = 20.0)
{
	ShapePtr shape;
	switch (in.Int(0, 6))
	{
	case 0:
		shape = MakeCircle(in.Positive(minSize, maxSize));
		break;
	case 1:
	{
		const double a = in.Positive(minSize, maxSize);
		shape = MakeEllipse(a, in.Positive(minSize, maxSize));
		break;
	}
	case 2:
	{
		const double a = in.Positive(minSize, maxSize), b = in.Positive(minSize, maxSize);
		const double n = in.Int(1, 12);
		shape = MakeSuperellipse(a, b, n, in.Int(1, 12));
		break;
	}
	case 3:
	{
		const double a = in.Positive(minSize, maxSize), b = in.Positive(minSize, maxSize);
		const double n = in.Number(1.0, 12.0);
		shape = MakeSuperellipse(a, b, n, in.Number(1.0, 12.0));
		break;
	}
	case 4:
	{
		const double a = in.Positive(minSize, maxSize), b = in.Positive(minSize, maxSize);
		shape = SuperellipseShape::FromZeta(a, b, in.Number(0.5, 6.0));
		break;
	}
	case 5:
	{
		const double size = in.Positive(minSize, maxSize);
		shape = MakeHeart(in.Bool() ? size * size : size); // α is a squared length
		break;
	}
	default:
		return DecodeUserShape(in);
	}
	Context() += shape->Describe() + " ";
	return shape;
}

/// A pose whose position is `scale` times a number mostly in [-range, range] and whose angle is
/// mostly in [-π, π]; either may be extreme or not finite.
inline Pose DecodePose(FuzzInput& in, double scale, double range)
{
	const double x = scale * in.Number(-range, range);
	const double y = scale * in.Number(-range, range);
	const Pose pose(Vec2(x, y), in.Number(-kPi, kPi));
	Context() += Describe(pose) + " ";
	return pose;
}

/// Every field of a pose is finite.
inline bool IsFinite(const Pose& p) { return b2a::IsFinite(p.p) && std::isfinite(p.q.c) && std::isfinite(p.q.s); }

/// The promises of ContactResult: no field is NaN, even when failed; when not failed every field
/// is finite and `touching` is "separation ≤ 0"; for `ordinary` input (every number from its
/// ordinary range) the normal is a unit vector. Where lengths reach 1e300 the normal may
/// underflow: it is still finite, and the fuzzer reports those cases separately.
inline void CheckContact(const ContactResult& c, bool ordinary)
{
	B2A_FUZZ_CHECK(c.failure != nullptr);
	B2A_FUZZ_CHECK(!std::isnan(c.level) && NotNaN(c.point) && NotNaN(c.normal) && NotNaN(c.pointA) && NotNaN(c.pointB) &&
	               !std::isnan(c.separation));
	if (!c.Ok())
		return;
	B2A_FUZZ_CHECK(std::isfinite(c.level) && IsFinite(c.point) && IsFinite(c.normal) && IsFinite(c.pointA) &&
	               IsFinite(c.pointB) && std::isfinite(c.separation));
	B2A_FUZZ_CHECK(c.touching == (c.separation <= 0.0));
	B2A_FUZZ_CHECK(!ordinary || std::fabs(Length(c.normal) - 1.0) < 1e-9);
}

/// The promises of LevelResult: no field is NaN; when not failed every field is finite, and for
/// ordinary input the normal is a unit vector.
inline void CheckLevel(const LevelResult& r, bool ordinary)
{
	B2A_FUZZ_CHECK(r.failure != nullptr);
	B2A_FUZZ_CHECK(!std::isnan(r.level) && NotNaN(r.point) && NotNaN(r.normal) && !std::isnan(r.multiplier));
	if (!r.Ok())
		return;
	B2A_FUZZ_CHECK(std::isfinite(r.level) && IsFinite(r.point) && IsFinite(r.normal) && std::isfinite(r.multiplier));
	B2A_FUZZ_CHECK(!ordinary || std::fabs(Length(r.normal) - 1.0) < 1e-9);
}

} // namespace b2a::fuzz
