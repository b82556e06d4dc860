// b2analytic: the common level of two ellipses by Perram and Wertheim's one-dimensional form.
#include "contact/SolverCore.h"

#include "b2analytic/SuperellipseShape.h"
#include "numerics/CodeLayout.h"
#include "numerics/RootFinding.h"
#include "numerics/SmallLinear.h"

#include <algorithm>
#include <cmath>

namespace b2a
{

namespace
{
// λ(x) = (x − c)ᵀ M (x − c) with M = R diag(1/a², 1/b²) Rᵀ (world frame, centre c). For n = 2
// the shape's hessX = n(n − 1)/a² is 2/a², so half of it is 1/a² to the bit, without the two
// divisions a query, which the first Halley step waited for. Rotate's R H Rᵀ with H diagonal
// written out: its terms in H's zero off-diagonal add a signed zero each, so the entries are
// Rotate's to the bit (but for the sign of a zero xy), in fewer operations.
Sym22 LevelMatrix(const SuperellipseShape& s, const Pose& p)
{
	const SuperellipseTerms& t = s.Terms();
	const double c = p.q.c, sn = p.q.s, hx = 0.5 * t.hessX, hy = 0.5 * t.hessY;
	return {c * c * hx + sn * sn * hy, c * sn * (hx - hy), sn * sn * hx + c * c * hy};
}

double Quad(const Sym22& m, Vec2 v) { return Dot(v, m * v); }

// The rounding of hi = p − q, per component: p − q = hi + low exactly (Knuth's TwoSum).
Vec2 TwoDifferenceLow(Vec2 p, Vec2 q, Vec2 hi)
{
	auto low = [](double a, double b, double s) {
		const double bb = s - a;
		return (a - (s - bb)) + (b - bb);
	};
	return {low(p.x, -q.x, hi.x), low(p.y, -q.y, hi.y)};
}

// SolveEllipsePairLevel's step far from the root (below), Halley's on the quartic Q = h·D²
// (D = det H), from h, h' and h''/2 = q there:
//   Q'/D² = h' + 2h·D'/D,  Q''/D² = h'' + 4h'·D'/D + 2h·((D'/D)² + D''/D),
// D' = tr(adj(H)·G), D'' = 2 det G (D is quadratic in s); Newton's on Q where Halley's is not to
// be trusted either, and on h where Q falls no more. Out of line: its code inlined in the loop
// made every warm contact dearer, though a warm start seldom takes it.
B2A_NOINLINE
double QuarticStep(const Sym22& H, const Sym22& G, double inv, double h, double slope, double q)
{
	const double ddet = (G.xx * H.yy + H.xx * G.yy - 2.0 * H.xy * G.xy) * inv; // D'/D
	const double a1 = slope + 2.0 * h * ddet;
	const double a2 = 2.0 * q + 4.0 * slope * ddet + 2.0 * h * (ddet * ddet + 2.0 * (G.xx * G.yy - G.xy * G.xy) * inv);
	if (!(a1 < 0.0))
		return -h / slope;
	if (std::fabs(h * a2) < a1 * a1)
		return -2.0 * h * a1 / (2.0 * a1 * a1 - h * a2);
	return -h / a1;
}

// ContactFromLevel's rule for an ellipse's point on the line X + t·dir, from the line's quadratic
// A t² + 2B t + (λ − 1) in the level λ (λ the level at X): X itself when λ is within 1e-10 of 1,
// the larger root where the line crosses, where it misses beyond rounding the radial point (only
// then computed), and false where neither applies (X inside yet missed, or grazing to rounding:
// the caller searches).
template <class Radial>
bool LineRule(Vec2 X, Vec2 dir, double A, double B, double level, Radial radial, Vec2& point)
{
	if (std::fabs(level - 1.0) <= 1e-10)
	{
		point = X;
		return true;
	}
	double far = 0.0;
	switch (QuadraticFarRoot(A, B, level - 1.0, far))
	{
	case LineQuadratic::crosses:
		point = X + far * dir;
		return true;
	case LineQuadratic::misses:
		if (!(level > 1.0))
			return false;
		point = radial();
		return true;
	case LineQuadratic::unknown:
		break;
	}
	return false;
}

// A cold start for elongated pairs. Scaled by k about their centres, two convex particles touch
// where k first reaches max over unit u of (r·u)/(hA(u) + hB(u)) (r the centre offset, h the
// support function: the separating-axis test solved for the scale), and for ellipses k² is the
// common level C. At the maximising normal u the touching points are k·ΣA·u/hA(u) on A and the
// like on B (Σ = R diag(a², b²) Rᵀ, h(u) = √(uᵀΣu)), where ∇λ = 2u/(k·h(u)): the multiplier of
// ∇λA + μ∇λB = 0 is μ = hB(u)/hA(u). So μ is taken at the best of five normals: the centre line
// and the four axes. Crossing needles meet tip to side, where the normal is the side's axis:
// the centre line's radii (the circles' answer) put their μ two decades off at 1000:1, these a
// tenth of a decade, which saves Halley's steps. Along a body's own axes h is a semi-axis, so the
// five take six square roots. Out of line: inlined into the solver it made every ellipse contact
// dearer, warm ones and rounder pairs that never call it included.
B2A_NOINLINE
double SupportStart(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb, Vec2 rc)
{
	const double aA = a.A(), bA = a.B(), aB = b.A(), bB = b.B();
	const Rot q = InvMul(pa.q, pb.q); // B's axes in A's frame
	const double c2 = q.c * q.c, s2 = q.s * q.s;
	const Vec2 rA = InvRotate(pa.q, rc), rB = InvRotate(pb.q, rc);
	// Candidates: (r·u, hA(u), hB(u)), the centre line's unnormalised (its F and μ are ratios).
	const double HA = std::sqrt(aA * aA * rA.x * rA.x + bA * bA * rA.y * rA.y);
	const double HB = std::sqrt(aB * aB * rB.x * rB.x + bB * bB * rB.y * rB.y);
	const double along[5] = {LengthSquared(rc), std::fabs(rA.x), std::fabs(rA.y), std::fabs(rB.x), std::fabs(rB.y)};
	const double hA[5] = {HA, aA, bA, std::sqrt(aA * aA * c2 + bA * bA * s2), std::sqrt(aA * aA * s2 + bA * bA * c2)};
	const double hB[5] = {HB, std::sqrt(aB * aB * c2 + bB * bB * s2), std::sqrt(aB * aB * s2 + bB * bB * c2), aB, bB};
	int best = 0;
	double bestF = along[0] / (hA[0] + hB[0]);
	for (int k = 1; k < 5; ++k)
	{
		const double F = along[k] / (hA[k] + hB[k]);
		if (F > bestF)
		{
			bestF = F;
			best = k;
		}
	}
	return hB[best] / (hA[best] + hB[best]); // s = μ/(1 + μ)
}

// A power of two and its inverse, both exact.
struct PowerOfTwo
{
	double value, inverse;
};

// The power of two σ with σ·x in [1, 2) for a positive normal x, and its inverse, both normal
// (the exponent clamped to ±1022: zero and NaN give 2^1022, infinities 2^−1022, and the solve
// then fails on its own tests).
B2A_NOINLINE // (a call, so that the caller branches around it: see SolveEllipsePairLevel)
PowerOfTwo PowerOfTwoInto12(double x)
{
	const int e = std::clamp(std::ilogb(x), -1022, 1022);
	return {std::ldexp(1.0, -e), std::ldexp(1.0, e)};
}

} // namespace

bool EllipseLinePoint(const SuperellipseShape& s, const Pose& p, Vec2 X, Vec2 dir, Vec2& point)
{
	// In the body frame scaled by the semi-axes, u = x/a, v = y/b and the level (f or f^1, the
	// two plain-ellipse forms) is u² + v². Along the line, with du, dv the scaled direction, it is
	// SuperellipseShape::FarCrossing's quadratic; where the line misses (LineMisses' rule) the
	// radial point is x/√λ(x), the level being homogeneous of degree 2. Inline, with the level
	// computed once: the virtual Level, FarCrossing and LineMisses calls were a quarter of a warm
	// 100:1 contact.
	const SuperellipseTerms& t = s.Terms();
	const Vec2 x = ToBody(p, X), d = InvRotate(p.q, dir);
	const double u = x.x * t.invA, v = x.y * t.invB, du = d.x * t.invA, dv = d.y * t.invB;
	const double level = u * u + v * v;
	return LineRule(X, dir, du * du + dv * dv, u * du + v * dv, level, [&] { return ToWorld(p, x / std::sqrt(level)); }, point);
}

namespace
{
// The pair's level matrices, their difference and the centre offset (A's centre to B's), which
// every part of the solve below shares.
struct EllipsePair
{
	Sym22 MA, MB; // λ(x) = (x − c)ᵀM(x − c) of each
	Sym22 G;      // MB − MA = dH/ds
	Vec2 rc;      // pb.p − pa.p
};

// The start of the multiplier s = μ/(1 + μ): the previous step's multiplier, or cold the
// circles' answer with each ellipse's radius along the centre line (exact for circles), beyond
// aspect 4 SupportStart's (up to aspect 4 the circles' answer is the better start: fewer Halley
// steps follow it; beyond, fewer follow the supports').
double StartMultiplier(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                       const EllipsePair& e, const WarmStart* warm)
{
	auto elongated = [](const SuperellipseShape& k) { return std::max(k.A(), k.B()) > 4.0 * std::min(k.A(), k.B()); };
	if (warm && warm->valid && warm->multiplier > 0.0 && std::isfinite(warm->multiplier))
		return warm->multiplier / (1.0 + warm->multiplier);
	if (!elongated(a) && !elongated(b))
	{
		const Vec2 u = Normalize(e.rc);
		const double rhoA = 1.0 / std::sqrt(Quad(e.MA, u)), rhoB = 1.0 / std::sqrt(Quad(e.MB, u));
		return rhoB / (rhoA + rhoB);
	}
	return SupportStart(a, pa, b, pb, e.rc);
}

// Where Halley's iteration on h(s) ended: the multiplier s, and x(s) and w = H⁻¹d at the last
// solved s (`solvedAt`), from which x(s) follows to first order (x' = −½w).
struct MultiplierRoot
{
	double s;
	Vec2 x, w;
	double solvedAt;
	int iterations;
	const char* failure; // set where the iteration failed, else null
};

// Halley's method on h, which the second derivative makes cheap: differentiating
// H·x' = −d/2 once more gives H·x'' = G·w with w = H⁻¹d and G = MB − MA, and
//   h'' = d'·x' + d·x'' = ½ wᵀG w + wᵀG w = (3/2) wᵀG w   (d' = 2G·x' = −G·w).
// With c = h''/(2h') and the Newton step δ = −h/h' the Halley step is δ/(1 + cδ), cubically
// convergent: a warm start 1e-3 off is at 1e-9 after one step and done after the second.
// Newton's error after δ is |c|·δ², and Halley's is smaller still: once that is below `settle`
// of s (or of 1 − s: 1e-17), the step is the last, taken without a further solve (x moves by
// x'·δ = −½w·δ, exact to |x''|δ² ~ 1e-17 of the size). Steps leaving the bracket bisect it.
// Needles (beyond aspect 16) stop at settle = 1e-8 instead: the refining Newton steps on (x, s)
// after the loop square what is left, so the loop's last step is spared (a second refining step
// is then seldom needed).
MultiplierRoot SolveMultiplier(const EllipsePair& e, double s, double settle)
{
	MultiplierRoot m;
	m.failure = nullptr;
	Vec2 x, w;           // x(s) and w = H⁻¹d at the last solved s
	double solvedAt = s; // that s
	int it = 1;
	const Sym22 &MA = e.MA, &MB = e.MB, &G = e.G;
	const Vec2 rc = e.rc;
	const Vec2 mbrc = MB * rc;
	double lo = 0.0, hi = 1.0;
	// σ: 1, or where det(H) (halfway, 1e12 at aspect 1000 and size 0.02) is beyond 1e±20, a power
	// of two near its inverse, so that the loop's k⁶ (k = σ·det(H)) neither overflows nor
	// underflows at any size (multiplying by σ rounds nothing). Not taken for sizes of 1e-3 to
	// 1e3, it costs a warm contact nothing, where σ taken from the bits every time would not.
	const double halfway = 0.25 * ((MA.xx + MB.xx) * (MA.yy + MB.yy) - (MA.xy + MB.xy) * (MA.xy + MB.xy));
	PowerOfTwo sigma{1.0, 1.0};
	if (!(halfway >= 1e-20 && halfway <= 1e20))
		sigma = PowerOfTwoInto12(halfway);
	const Sym22 MAs = sigma.value * MA, MBs = sigma.value * MB; // exact
	const Vec2 mbrcS = sigma.value * mbrc;
	for (;; ++it)
	{
		const Sym22 H = (1.0 - s) * MA + s * MB;
		const double det = H.xx * H.yy - H.xy * H.xy;
		if (!(det > 0.0))
		{
			m.failure = "ellipse pair: singular weighted level matrix";
			break;
		}
		// The step does not wait for 1/det. With adj(H) = det·H⁻¹ and k = σ·det (σ above):
		// X = adj(H)·s·σMB·r = k·x, and from it, with σMA and σMB (x − r, ∇λ and d are linear in
		// x), d̃ = σk·d and w̃ = adj(H)·d̃ = k²·w, so that h, h' and Q' are computed σk², σk³ and
		// k⁴ times over. The Halley step −h·h'/(h'² − h·Q') is then −k·h̃·h̃'/(h̃'² − σ·h̃·Q̃'), and
		// its tests take factors σ and σk; 1/det, for x and w themselves, runs beside the step,
		// off the chain that a warm solve waits for. The scaled quantities keep the plain names
		// (h, slope, q) below.
		const double inv = 1.0 / det;
		const double k = sigma.value * det; // exact
		const Vec2 rhs = s * mbrcS;
		const Vec2 X(H.yy * rhs.x - H.xy * rhs.y, H.xx * rhs.y - H.xy * rhs.x); // k·x
		const Vec2 XB = X - k * rc;                                          // k·(x − r)
		const Vec2 gA = MAs * X, gB = MBs * XB;
		const double h = Dot(XB, gB) - Dot(X, gA); // σk²·h
		const Vec2 d = 2.0 * (gB - gA);            // σk·d
		const Vec2 wk(H.yy * d.x - H.xy * d.y, H.xx * d.y - H.xy * d.x); // k²·w
		const double unscale = inv * sigma.inverse; // 1/k
		x = unscale * X;
		w = (unscale * unscale) * wk;
		solvedAt = s;
		if (!std::isfinite(h)) // (a non-finite x or w makes h non-finite too)
		{
			m.failure = "ellipse pair: non-finite answer";
			break;
		}
		if (h == 0.0)
			break;
		// (Selects, not branches: near the root h's sign is rounding's, which no predictor
		// foresees.)
		lo = h > 0.0 ? s : lo;
		hi = h < 0.0 ? s : hi;
		const double slope = -0.5 * Dot(d, wk); // σk³·h'
		const double relativeTo = std::min(s, 1.0 - s);
		double next = 0.5 * (lo + hi); // bisection unless the step below stays in the bracket
		if (slope < 0.0)
		{
			// δ = −h/h', c·δ = −hQ'/h'² with Q' = 0.75 wᵀGw = h''/2, and the Halley step
			// δ/(1 + cδ) = −h·h'/(h'² − h·Q'): one division, a chain of them being what a warm
			// solve waits for.
			// Where |cδ| ≥ ½ (far from the root) h is far from linear: it is a rational function
			// of s whose poles are where H is singular (negative multipliers, which the pencil
			// (MA, MB) places), and between 1000:1 needles it falls like 1/μ² over decades of
			// μ = s/(1 − s), where each Newton step grows s by half at most (from a warm start
			// 1e-4 of the multiplier off: up to 23 steps). Times det(H)², whose zeros those poles
			// are, it is a quartic in s, and the step there is Halley's on that (QuarticStep):
			// up to 12 steps then.
			const double q = 0.75 * Quad(G, wk); // k⁴·Q'
			const double slope2 = slope * slope, hq = sigma.value * h * q;
			const bool halleyOk = std::fabs(hq) < 0.5 * slope2;
			double step = -k * h * slope / (slope2 - hq);
			if (!halleyOk)
			{
				const double u = 1.0 / k, u2 = u * u;
				step = QuarticStep(H, G, inv, h * u2 * sigma.inverse, slope * u2 * u * sigma.inverse, q * u2 * u2);
			}
			// Converged: Newton's error |c|δ² = |h²Q'|/|h'|³ at most `settle` of s (or 1 − s).
			// (Near the root h is rounding noise whose sign may be wrong: the converged step is not
			// tested against the bracket, or a converged s would bisect the whole bracket.)
			if (halleyOk && k * std::fabs(hq * h) <= settle * relativeTo * std::fabs(slope2 * slope))
			{
				s += step;
				break;
			}
			if (s + step > lo && s + step < hi)
				next = s + step;
		}
		s = next;
		if (hi - lo <= 4e-16 * relativeTo)
			break;
		if (it == 100)
		{
			m.failure = "ellipse pair: iteration cap reached";
			break;
		}
	}
	m.s = s;
	m.x = x;
	m.w = w;
	m.solvedAt = solvedAt;
	m.iterations = it;
	return m;
}

// What the solve ends with: the level's gradients (halved: M·v) and values at the point, the
// point, the normal and the level.
struct EllipsePairAnswer
{
	Vec2 gA, gB;  // MA·x and MB·(x − r), half of ∇λA and ∇λB
	double lamA, lamB;
	Vec2 point;   // the world point
	Vec2 normal;  // the unit normal, once computed (zero until then)
	double level; // F(s): flat at the maximum, so s's rounding hardly moves it
	double s;     // the multiplier s = μ/(1 + μ), refined with the point for needles
};

// The point of the multiplier for pairs up to aspect 16, where H's condition is at most 256 and
// H's own x keeps the point at rounding level without refining steps (docs/benchmarks.md has
// the errors); with ContactFromLevel's points where `points` asks for them.
void PointOfMultiplier(const EllipsePair& e, const Pose& pa, const Pose& pb, const MultiplierRoot& m, EllipsePairPoints* points,
                       EllipsePairAnswer& ans)
{
	const double s = m.s;
	const Vec2 x = m.x - (0.5 * (s - m.solvedAt)) * m.w; // x(s) from the last solve, x' = −½w
	ans.gA = e.MA * x;
	ans.lamA = Dot(x, ans.gA);
	ans.gB = e.MB * (x - e.rc);
	ans.lamB = Dot(x - e.rc, ans.gB);
	ans.level = (1.0 - s) * ans.lamA + s * ans.lamB;
	ans.s = s;
	ans.point = pa.p + x;
	if (points && LengthSquared(ans.gA) > 0.0)
	{
		// ContactFromLevel's points, from what is at hand: along the line X + t·n, λA is
		// λA(X) + 2t·n·MA·x + t²·nᵀMA·n, and likewise for B along −n. The larger root of each
		// quadratic is the far crossing (the on-surface rule and the root's form as in
		// SuperellipseShape::FarCrossing); a level within 1e-10 of 1 is its own crossing. Where
		// the line misses the ellipse (no real root beyond rounding, SuperellipseShape::
		// LineMisses' rule), ContactFromLevel's radial point: the centre plus the offset to X
		// over √λ (λ is homogeneous of degree 2 in the offset).
		// The lines run along gA itself, not its unit vector: the quadratics' roots scale with
		// the direction and the points do not, and the crossings need not wait for the
		// normal's square root and division.
		ans.normal = Normalize(ans.gA);
		auto crossing = [&](const Sym22& M, Vec2 dir, Vec2 g, double lam, Vec2 centre, Vec2 offset, Vec2& at) {
			return LineRule(ans.point, dir, Quad(M, dir), Dot(dir, g), lam, [&] { return centre + offset / std::sqrt(lam); }, at);
		};
		points->valid = crossing(e.MA, ans.gA, ans.gA, ans.lamA, pa.p, x, points->a) &&
		                crossing(e.MB, -ans.gA, ans.gB, ans.lamB, pb.p, x - e.rc, points->b);
	}
}

// Needles (beyond aspect 16): Newton steps on the pair (x, s), H·δx + ½d·δs = −(H·x − s·MB·r)
// and d·δx = −h (one, mostly: see `settled`), from residuals computed without H. H's entries
// mix 1/a² and 1/b², so each carries a rounding of 1e-16 of the large one, 1e-10 of the small one
// at aspect 1000, and that is how far H's own x is off; the residual (1 − s)·MA·x + s·MB·(x − r),
// with each M applied in its body frame (rotate, scale by the axes, rotate back), is exact to a
// rounding of the gradients instead. The step solves with H as the loop did, which only the
// step's own size multiplies (cond·1e-16 of 1e-10 of the size): the bordered system
// [[H, d/2], [dᵀ, 0]], by SolveBorderedSolution as the superellipse finish solves its own; a
// singular one, or a multiplier leaving (0, 1), ends the steps. The centre offset is carried
// exactly (TwoSum) so that B's position loses nothing either. (This replaced a finish in long
// double that took half of a warm 100:1 contact.)
void RefinedNeedlePoint(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                        const EllipsePair& e, MultiplierRoot m, EllipsePairPoints* points, EllipsePairAnswer& ans)
{
	const Sym22 &MA = e.MA, &MB = e.MB;
	const Vec2 rc = e.rc;
	const SuperellipseTerms& ta = a.Terms();
	const SuperellipseTerms& tb = b.Terms();
	const Vec2 rcLow = TwoDifferenceLow(pb.p, pa.p, rc);
	// Half the gradient (M·v) and the level (vᵀM v) of one ellipse at v from its centre.
	auto halfGradient = [](const SuperellipseTerms& t, Rot q, Vec2 v, double& lam) {
		const Vec2 u = InvRotate(q, v);
		const Vec2 g(0.5 * t.hessX * u.x, 0.5 * t.hessY * u.y);
		lam = u.x * g.x + u.y * g.y;
		return Rotate(q, g);
	};
	double s = m.s;
	Vec2 x = m.x - (0.5 * (s - m.solvedAt)) * m.w;
	double lamA = 0.0, lamB = 0.0;
	Vec2 gA, gB;
	for (int pass = 0;; ++pass)
	{
		gA = halfGradient(ta, pa.q, x, lamA);
		gB = halfGradient(tb, pb.q, (x - rc) - rcLow, lamB);
		if (pass == 4)
			break;
		const Vec2 res = (1.0 - s) * gA + s * gB, d = 2.0 * (gB - gA);
		const Sym22 H = (1.0 - s) * MA + s * MB;
		const double minusR[3] = {-res.x, -res.y, lamA - lamB};
		double delta[3];
		if (!SolveBorderedSolution(H.xx, H.xy, H.yy, 0.5 * d.x, 0.5 * d.y, d.x, d.y, minusR, delta) ||
		    !(s + delta[2] > 0.0 && s + delta[2] < 1.0))
			break;
		const Vec2 dx(delta[0], delta[1]);
		const double ds = delta[2];
		// Settled when the step is below 1e-10 of the offset from the nearer centre: H's
		// roundings leave at most cond·1e-16 of it (1e-10 at aspect 1000), and the next step
		// would be at rounding level. A larger step (a pair of very unequal sizes, whose point is
		// far from the large one's centre, or a loop that ended by bisection) takes another, up
		// to four.
		const bool settled = LengthSquared(dx) <= 1e-20 * std::min(LengthSquared(x), LengthSquared(x - rc));
		s += ds;
		x = x + dx;
		if (settled)
		{
			// The gradients and levels at x + dx from those at x, exactly (they are linear and
			// quadratic in x): no second pass of rotations, and no rounding of x + dx in them.
			const Vec2 dgA = MA * dx, dgB = MB * dx;
			lamA += Dot(dx, 2.0 * gA + dgA);
			lamB += Dot(dx, 2.0 * gB + dgB);
			gA = gA + dgA;
			gB = gB + dgB;
			break;
		}
	}
	ans.gA = gA;
	ans.gB = gB;
	ans.lamA = lamA;
	ans.lamB = lamB;
	ans.level = (1.0 - s) * lamA + s * lamB;
	ans.s = s;
	ans.point = pa.p + x;
	// The normal from the better-conditioned of the two parallel gradients (equal in direction at
	// the root, to the step's rounding). Each gradient is off by the rounding of its body
	// coordinates, 1e-16·|v|, times the stiffer axis 1/b², and at a needle's tip, where the
	// gradient is only 1/a, that is a relative 1e-16·(a/b)²: 1e-10 at 1000:1. The other
	// particle's side has the gradient 1/b there and keeps the normal to 1e-13. So each error
	// bound |v|·max(1/a², 1/b²)/|g| is compared, crosswise and squared.
	const Vec2 xb = x - rc;
	const double kA = 0.5 * std::max(ta.hessX, ta.hessY), kB = 0.5 * std::max(tb.hessX, tb.hessY);
	const bool fromB = LengthSquared(x) * kA * kA * LengthSquared(gB) > LengthSquared(xb) * kB * kB * LengthSquared(gA);
	ans.normal = Normalize(fromB && LengthSquared(gB) > 0.0 ? -gB : gA);
	if (points && LengthSquared(ans.normal) > 0.0)
	{
		// The points in each body frame, where the levels carry no rotation's rounding.
		points->valid = EllipseLinePoint(a, pa, ans.point, ans.normal, points->a) &&
		                EllipseLinePoint(b, pb, ans.point, -ans.normal, points->b);
	}
}

// Whether the answer solves the conditions. The gradients are opposed by construction: x(s)
// minimises (1 − s)λA + s·λB, so (1 − s)∇λA + s∇λB = 0 at it for any s (to the rounding of its
// 2×2 solve, or of the refining steps' residual). So the levels' mismatch decides, first in
// squares (within 1e-11, no root or division: every answer at rounding level), else by
// ConditionsHold on the levels λ themselves, whose gradients are 2·M·v and Hessians 2·M.
bool EllipseConditionsHold(const EllipsePair& e, const Pose& pa, const Pose& pb, const EllipsePairAnswer& ans)
{
	const double d = ans.lamA - ans.lamB;
	if (d * d <= 1e-22 * ans.lamA * ans.lamA)
		return true;
	const double reach = std::max({Length(ans.point), Length(pa.p), Length(pb.p)});
	return ConditionsHold(ans.lamA, ans.lamB, 2.0 * ans.gA, 2.0 * ans.gB, 2.0 * e.MA, 2.0 * e.MB,
	                      std::numeric_limits<double>::epsilon() * reach, 1.0);
}
} // namespace

LevelResult SolveEllipsePairLevel(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                  const WarmStart* warm, EllipsePairPoints* points)
{
	if (points)
		points->valid = false;
	// Perram–Wertheim: F(s) = min_x (1 − s)·λA(x) + s·λB(x) is concave in s ∈ [0, 1] and its
	// maximum is the common level C (both particles scaled by √C about their centres touch).
	// With H(s) = (1 − s)MA + s·MB the minimiser solves H·x = s·MB·r (x from A's centre, r the
	// centre offset), and by the envelope theorem F'(s) = h(s) = λB(x) − λA(x), which falls from
	// λB(cA) > 0 at s = 0 to −λA(cB) < 0 at s = 1; its root is the maximiser, where λA = λB = C.
	// Differentiating H·x = s·MB·r: H·x' = MB(r − x) + MA·x = −(∇λB − ∇λA)/2, so
	// h'(s) = (∇λB − ∇λA)·x' = −½ dᵀH⁻¹d with d = ∇λB − ∇λA: negative, so h has one root, which
	// Halley's method (SolveMultiplier) finds from a bracket that bisection keeps. At the root
	// (1 − s)∇λA + s∇λB = 0, so the multiplier of ∇λA + μ∇λB = 0 (and of the ψ = √λ gradients,
	// equal at λA = λB) is s/(1 − s). Each step is a 2×2 solve: no shape evaluation.
	LevelResult r;
	r.method = SolveMethod::ellipsePair;
	EllipsePair e;
	e.MA = LevelMatrix(a, pa);
	e.MB = LevelMatrix(b, pb);
	e.G = Sym22{e.MB.xx - e.MA.xx, e.MB.xy - e.MA.xy, e.MB.yy - e.MA.yy};
	e.rc = pb.p - pa.p;
	if (!(LengthSquared(e.rc) > 0.0))
	{
		r.failure = "coincident centres: no common-level point between them";
		return r;
	}
	auto moderate = [](const SuperellipseShape& k) { return std::max(k.A(), k.B()) <= 16.0 * std::min(k.A(), k.B()); };
	const bool needles = !(moderate(a) && moderate(b));
	const MultiplierRoot m = SolveMultiplier(e, StartMultiplier(a, pa, b, pb, e, warm), needles ? 1e-8 : 1e-17);
	r.iterations = m.iterations;
	if (m.failure)
	{
		r.failure = m.failure;
		return r;
	}
	// The point of the multiplier. H's condition grows like the aspect ratio squared (1e6 for
	// 1000:1 needles), and its entries mix 1/a² and 1/b² through the rotation, so H's own x would
	// be off by up to 1e-10 of the size there: needles take refining steps.
	EllipsePairAnswer ans;
	if (!needles)
		PointOfMultiplier(e, pa, pb, m, points, ans);
	else
		RefinedNeedlePoint(a, pa, b, pb, e, m, points, ans);
	if (!IsFinite(ans.point) || !std::isfinite(ans.level) || !std::isfinite(ans.lamA) || !(LengthSquared(ans.gA) > 0.0))
	{
		r.failure = "ellipse pair: non-finite answer";
		return r;
	}
	if (!EllipseConditionsHold(e, pa, pb, ans))
	{
		if (points)
			points->valid = false;
		r.failure = "ellipse pair: stopped short of a solution (its levels or normals disagree beyond rounding)";
		return r;
	}
	r.status = SolveStatus::converged;
	r.level = ans.level;
	r.point = ans.point;
	r.normal = LengthSquared(ans.normal) > 0.0 ? ans.normal : Normalize(ans.gA);
	r.multiplier = ans.s / (1.0 - ans.s);
	return r;
}

} // namespace b2a
