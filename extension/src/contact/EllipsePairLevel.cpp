// b2analytic: the common level of two ellipses by Perram and Wertheim's one-dimensional form.
#include "contact/SolverCore.h"

#include "b2analytic/SuperellipseShape.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <typeinfo>

namespace b2a
{

namespace
{
// λ(x) = (x − c)ᵀ M (x − c) with M = R diag(1/a², 1/b²) Rᵀ (world frame, centre c). For n = 2
// the shape's hessX = n(n − 1)/a² is 2/a², so half of it is 1/a² to the bit, without the two
// divisions a query, which the first Halley step waited for.
Sym22 LevelMatrix(const SuperellipseShape& s, const Pose& p)
{
	const SuperellipseTerms& t = s.Terms();
	return Rotate(p.q, Sym22{0.5 * t.hessX, 0.0, 0.5 * t.hessY});
}

double Quad(const Sym22& m, Vec2 v) { return Dot(v, m * v); }

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

const SuperellipseShape* AsPlainEllipse(const Shape& s)
{
	if (s.Family() != ShapeFamily::ellipse && s.Family() != ShapeFamily::circle)
		return nullptr;
	// The class is final: comparing the dynamic type is exact and costs less than a dynamic_cast
	// (two per contact between ellipses). A superellipse is in these families exactly when
	// n = m = 2, with the level f itself (ζ = 0) or f^(1/1) (ζ = 1, the only ζ with n = 2ζ = 2);
	// another Shape subclass may claim the family, hence the type test.
	return typeid(s) == typeid(SuperellipseShape) ? static_cast<const SuperellipseShape*>(&s) : nullptr;
}

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
	// Halley's method below finds from a bracket that bisection keeps. At the root (1 − s)∇λA + s∇λB = 0,
	// so the multiplier of ∇λA + μ∇λB = 0 (and of the ψ = √λ gradients, equal at λA = λB) is
	// s/(1 − s). Each step is a 2×2 solve: no shape evaluation.
	LevelResult r;
	r.method = SolveMethod::ellipsePair;
	const Sym22 MA = LevelMatrix(a, pa), MB = LevelMatrix(b, pb);
	const Sym22 G{MB.xx - MA.xx, MB.xy - MA.xy, MB.yy - MA.yy}; // dH/ds
	const Vec2 rc = pb.p - pa.p;
	if (!(LengthSquared(rc) > 0.0))
	{
		r.failure = "coincident centres: no common-level point between them";
		return r;
	}
	// Start: the previous step's multiplier, or the circles' answer with each ellipse's radius
	// along the centre line (exact for circles).
	double s = 0.5;
	if (warm && warm->valid && warm->multiplier > 0.0 && std::isfinite(warm->multiplier))
	{
		s = warm->multiplier / (1.0 + warm->multiplier);
	}
	else
	{
		const Vec2 u = Normalize(rc);
		const double rhoA = 1.0 / std::sqrt(Quad(MA, u)), rhoB = 1.0 / std::sqrt(Quad(MB, u));
		s = rhoB / (rhoA + rhoB);
	}
	// Halley's method on h, which the second derivative makes cheap: differentiating
	// H·x' = −d/2 once more gives H·x'' = G·w with w = H⁻¹d and G = MB − MA, and
	//   h'' = d'·x' + d·x'' = ½ wᵀG w + wᵀG w = (3/2) wᵀG w   (d' = 2G·x' = −G·w).
	// With c = h''/(2h') and the Newton step δ = −h/h' the Halley step is δ/(1 + cδ), cubically
	// convergent: a warm start 1e-3 off is at 1e-9 after one step and done after the second.
	// Newton's error after δ is |c|·δ², and Halley's is smaller still: once that is below 1e-17
	// of s (or of 1 − s), the step is the last, taken without a further solve (x moves by
	// x'·δ = −½w·δ, exact to |x''|δ² ~ 1e-17 of the size). Steps leaving the bracket bisect it.
	const Vec2 mbrc = MB * rc;
	double lo = 0.0, hi = 1.0;
	Vec2 x, w;          // x(s) and w = H⁻¹d at the last solved s
	double solvedAt = s; // that s
	for (int it = 1;; ++it)
	{
		r.iterations = it;
		const Sym22 H = (1.0 - s) * MA + s * MB;
		const double det = H.xx * H.yy - H.xy * H.xy;
		if (!(det > 0.0))
		{
			r.failure = "ellipse pair: singular weighted level matrix";
			return r;
		}
		const double inv = 1.0 / det;
		const Vec2 rhs = s * mbrc;
		x = inv * Vec2(H.yy * rhs.x - H.xy * rhs.y, H.xx * rhs.y - H.xy * rhs.x);
		solvedAt = s;
		const Vec2 gA = MA * x, gB = MB * (x - rc);
		const double h = Dot(x - rc, gB) - Dot(x, gA);
		const Vec2 d = 2.0 * (gB - gA);
		w = inv * Vec2(H.yy * d.x - H.xy * d.y, H.xx * d.y - H.xy * d.x);
		if (!std::isfinite(h)) // (a non-finite x or w makes h non-finite too)
		{
			r.failure = "ellipse pair: non-finite answer";
			return r;
		}
		if (h > 0.0) lo = s;
		else if (h < 0.0) hi = s;
		else break;
		const double slope = -0.5 * Dot(d, w);
		const double relativeTo = std::min(s, 1.0 - s);
		double next = 0.5 * (lo + hi); // bisection unless the step below stays in the bracket
		if (slope < 0.0)
		{
			// δ = −h/h', c·δ = −hQ'/h'² with Q' = 0.75 wᵀGw = h''/2, and the Halley step
			// δ/(1 + cδ) = −h·h'/(h'² − h·Q'): one division, a chain of them being what a warm
			// solve waits for. Where |cδ| ≥ ½ (far from the root) the Newton step is taken.
			const double q = 0.75 * Quad(G, w);
			const double slope2 = slope * slope, hq = h * q;
			const bool halleyOk = std::fabs(hq) < 0.5 * slope2;
			const double step = halleyOk ? -h * slope / (slope2 - hq) : -h / slope;
			// Converged: Newton's error |c|δ² = |h²Q'|/|h'|³ at most 1e-17 of s (or 1 − s).
			// (Near the root h is rounding noise whose sign may be wrong: the converged step is not
			// tested against the bracket, or a converged s would bisect the whole bracket.)
			if (halleyOk && std::fabs(hq * h) <= 1e-17 * relativeTo * std::fabs(slope2 * slope))
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
			r.failure = "ellipse pair: iteration cap reached";
			return r;
		}
	}
	// The point of the last multiplier. H's condition grows like the aspect ratio squared (1e6
	// for 1000:1 needles), and its entries mix 1/a² and 1/b² through the rotation, so double
	// rounding there would cost the point up to 1e-10 of the size: needles finish in long double.
	// Up to aspect 16 the condition is at most 256 and double keeps the point at rounding level
	// (b2a_bench_pairs, warm 10:1 motions: 6e-15 of the size), and saves the long-double finish,
	// 40 % of a warm contact at aspect 10. (At aspect 100 double would still keep it to 7e-12,
	// inside the 1e-9 asked of contacts, but 250 times above the long-double finish's.)
	auto moderate = [](const SuperellipseShape& e) { return std::max(e.A(), e.B()) <= 16.0 * std::min(e.A(), e.B()); };
	Vec2 gA;            // MA·x, half of ∇λA: the normal's direction
	Vec2 normal;        // its unit vector, once computed
	Vec2 point;         // the world point
	double level = 0.0; // F(s): flat at the maximum, so s's rounding hardly moves it
	double lamA = 0.0;
	if (moderate(a) && moderate(b))
	{
		x = x - (0.5 * (s - solvedAt)) * w; // x(s) from the last solve, x' = −½w
		gA = MA * x;
		lamA = Dot(x, gA);
		const Vec2 gB = MB * (x - rc);
		const double lamB = Dot(x - rc, gB);
		level = (1.0 - s) * lamA + s * lamB;
		point = pa.p + x;
		if (points && LengthSquared(gA) > 0.0)
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
			// normal's square root and division (6 % of a warm contact at aspect 10).
			normal = Normalize(gA);
			auto crossing = [&](const Sym22& M, Vec2 dir, Vec2 g, double lam, Vec2 centre, Vec2 offset, Vec2& at) {
				return LineRule(point, dir, Quad(M, dir), Dot(dir, g), lam, [&] { return centre + offset / std::sqrt(lam); }, at);
			};
			points->valid = crossing(MA, gA, gA, lamA, pa.p, x, points->a) && crossing(MB, -gA, gB, lamB, pb.p, x - rc, points->b);
		}
	}
	else
	{
		using LD = long double;
		struct M2 { LD xx, xy, yy; };
		auto matrix = [](const SuperellipseShape& e, const Pose& p) {
			const LD c = p.q.c, sn = p.q.s, ia = 1.0L / (LD(e.A()) * e.A()), ib = 1.0L / (LD(e.B()) * e.B());
			return M2{c * c * ia + sn * sn * ib, c * sn * (ia - ib), sn * sn * ia + c * c * ib};
		};
		const M2 la = matrix(a, pa), lb = matrix(b, pb);
		const LD rx = LD(pb.p.x) - pa.p.x, ry = LD(pb.p.y) - pa.p.y;
		LD sl = s, px = 0, py = 0, levelA = 0, levelB = 0;
		// x(s), λA, λB; then (once) the Newton correction of s from h and h' in long double, whose
		// rounding no longer limits s as the double h's did.
		for (int pass = 0; pass < 2; ++pass)
		{
			const M2 h{(1 - sl) * la.xx + sl * lb.xx, (1 - sl) * la.xy + sl * lb.xy, (1 - sl) * la.yy + sl * lb.yy};
			const LD bx = sl * (lb.xx * rx + lb.xy * ry), by = sl * (lb.xy * rx + lb.yy * ry);
			const LD dl = h.xx * h.yy - h.xy * h.xy;
			px = (h.yy * bx - h.xy * by) / dl;
			py = (h.xx * by - h.xy * bx) / dl;
			const LD qx = px - rx, qy = py - ry;
			const LD gax = la.xx * px + la.xy * py, gay = la.xy * px + la.yy * py;
			const LD gbx = lb.xx * qx + lb.xy * qy, gby = lb.xy * qx + lb.yy * qy;
			levelA = px * gax + py * gay;
			levelB = qx * gbx + qy * gby;
			if (pass == 1)
				break;
			const LD dx = 2 * (gbx - gax), dy = 2 * (gby - gay);
			const LD wx = (h.yy * dx - h.xy * dy) / dl, wy = (h.xx * dy - h.xy * dx) / dl;
			const LD slopeL = -0.5L * (dx * wx + dy * wy);
			const LD next = sl - (levelB - levelA) / slopeL;
			if (slopeL < 0 && next > 0 && next < 1)
				sl = next;
		}
		s = double(sl);
		x = Vec2(double(px), double(py));
		lamA = double(levelA);
		gA = Vec2(double(la.xx * px + la.xy * py), double(la.xy * px + la.yy * py));
		level = double((1 - sl) * levelA + sl * levelB);
		point = Vec2(double(pa.p.x + LD(px)), double(pa.p.y + LD(py)));
		if (points && LengthSquared(gA) > 0.0)
		{
			// The points in each body frame, where the levels carry no rotation's rounding.
			normal = Normalize(gA);
			points->valid = EllipseLinePoint(a, pa, point, normal, points->a) && EllipseLinePoint(b, pb, point, -normal, points->b);
		}
	}
	if (!IsFinite(x) || !std::isfinite(level) || !std::isfinite(lamA) || !(LengthSquared(gA) > 0.0))
	{
		r.failure = "ellipse pair: non-finite answer";
		return r;
	}
	r.status = SolveStatus::converged;
	r.level = level;
	r.point = point;
	r.normal = LengthSquared(normal) > 0.0 ? normal : Normalize(gA);
	r.multiplier = s / (1.0 - s);
	return r;
}

} // namespace b2a
