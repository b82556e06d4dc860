// b2analytic: the common level of two ellipses by Perram and Wertheim's one-dimensional form.
#include "contact/SolverCore.h"

#include "b2analytic/SuperellipseShape.h"

#include <algorithm>
#include <cmath>
#include <typeinfo>

namespace b2a
{

namespace
{
// λ(x) = (x − c)ᵀ M (x − c) with M = R diag(1/a², 1/b²) Rᵀ (world frame, centre c).
Sym22 LevelMatrix(const SuperellipseShape& s, const Pose& p)
{
	return Rotate(p.q, Sym22{1.0 / (s.A() * s.A()), 0.0, 1.0 / (s.B() * s.B())});
}

double Quad(const Sym22& m, Vec2 v) { return Dot(v, m * v); }

// H⁻¹v for a symmetric positive definite 2×2 H, by its adjugate.
Vec2 SolveSpd(const Sym22& h, Vec2 v, double& det)
{
	det = h.xx * h.yy - h.xy * h.xy;
	return Vec2(h.yy * v.x - h.xy * v.y, h.xx * v.y - h.xy * v.x) / det;
}
} // namespace

const SuperellipseShape* AsPlainEllipse(const Shape& s)
{
	if (s.Family() != ShapeFamily::ellipse && s.Family() != ShapeFamily::circle)
		return nullptr;
	// The class is final: comparing the dynamic type is exact and costs less than a dynamic_cast
	// (two per contact between ellipses).
	const auto* e = typeid(s) == typeid(SuperellipseShape) ? static_cast<const SuperellipseShape*>(&s) : nullptr;
	// n = m = 2 with the level f itself (ζ = 0) or f^(1/1) (ζ = 1).
	return e && e->N() == 2.0 && e->M() == 2.0 && (e->Zeta() == 0.0 || e->Zeta() == 1.0) ? e : nullptr;
}

LevelResult SolveEllipsePairLevel(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                  const WarmStart* warm)
{
	// Perram–Wertheim: F(s) = min_x (1 − s)·λA(x) + s·λB(x) is concave in s ∈ [0, 1] and its
	// maximum is the common level C (both particles scaled by √C about their centres touch).
	// With H(s) = (1 − s)MA + s·MB the minimiser solves H·x = s·MB·r (x from A's centre, r the
	// centre offset), and by the envelope theorem F'(s) = h(s) = λB(x) − λA(x), which falls from
	// λB(cA) > 0 at s = 0 to −λA(cB) < 0 at s = 1; its root is the maximiser, where λA = λB = C.
	// Differentiating H·x = s·MB·r: H·x' = MB(r − x) + MA·x = −(∇λB − ∇λA)/2, so
	// h'(s) = (∇λB − ∇λA)·x' = −½ dᵀH⁻¹d with d = ∇λB − ∇λA: negative, and Newton on h from a
	// bracket that bisection keeps converges quadratically. At the root (1 − s)∇λA + s∇λB = 0,
	// so the multiplier of ∇λA + μ∇λB = 0 (and of the ψ = √λ gradients, equal at λA = λB) is
	// s/(1 − s). Each step is a 2×2 solve: no shape evaluation.
	LevelResult r;
	r.method = SolveMethod::ellipsePair;
	const Sym22 MA = LevelMatrix(a, pa), MB = LevelMatrix(b, pb);
	const Vec2 rc = pb.p - pa.p;
	if (!(LengthSquared(rc) > 0.0))
	{
		r.failure = "coincident centres: no common-level point between them";
		return r;
	}
	// Start: the circles' answer with each ellipse's radius along the centre line (exact for
	// circles), or the previous step's multiplier.
	const Vec2 u = Normalize(rc);
	const double rhoA = 1.0 / std::sqrt(Quad(MA, u)), rhoB = 1.0 / std::sqrt(Quad(MB, u));
	double s = rhoB / (rhoA + rhoB);
	if (warm && warm->valid && warm->multiplier > 0.0 && std::isfinite(warm->multiplier))
		s = warm->multiplier / (1.0 + warm->multiplier);
	double lo = 0.0, hi = 1.0;
	Vec2 x;
	double lamA = 0.0, lamB = 0.0;
	for (int it = 1; it <= 100; ++it)
	{
		r.iterations = it;
		const Sym22 H = (1.0 - s) * MA + s * MB;
		double det = 0.0;
		x = SolveSpd(H, s * (MB * rc), det);
		if (!(det > 0.0) || !IsFinite(x))
		{
			r.failure = "ellipse pair: singular weighted level matrix";
			return r;
		}
		lamA = Quad(MA, x);
		lamB = Quad(MB, x - rc);
		const double h = lamB - lamA;
		if (h > 0.0) lo = s;
		else if (h < 0.0) hi = s;
		else break;
		const Vec2 d = 2.0 * (MB * (x - rc) - MA * x);
		const double slope = -0.5 * Dot(d, SolveSpd(H, d, det));
		// Quadratic convergence: a Newton step of 1e-9 relative leaves an error of ~1e-18, below
		// what the rounding of h resolves, so it is the last one. (Near the root h is rounding
		// noise whose sign may be wrong: testing the step against the bracket there would throw
		// a converged s into bisection of the whole bracket.)
		const double relativeTo = std::min(s, 1.0 - s);
		const double newtonStep = slope < 0.0 ? -h / slope : 0.0;
		if (slope < 0.0 && std::fabs(newtonStep) <= 1e-9 * relativeTo)
		{
			s += newtonStep;
			break;
		}
		double next = s + newtonStep;
		if (!(slope < 0.0) || !(next > lo && next < hi))
			next = 0.5 * (lo + hi); // outside the bracket: bisect
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
	// rounding there would cost the point up to 1e-10 of the size: elongated pairs finish in long
	// double. Up to aspect 4 the condition is at most 16 and double keeps the point to ~1e-15.
	const double aspectA = std::max(a.A(), a.B()) / std::min(a.A(), a.B());
	const double aspectB = std::max(b.A(), b.B()) / std::min(b.A(), b.B());
	Vec2 gA;            // MA·x, half of ∇λA: the normal's direction
	Vec2 point;         // the world point
	double level = 0.0; // F(s): flat at the maximum, so s's rounding hardly moves it
	bool usable = true; // the double finish also checks its solve and λB
	if (std::max(aspectA, aspectB) <= 4.0)
	{
		const Sym22 H = (1.0 - s) * MA + s * MB;
		double det = 0.0;
		x = SolveSpd(H, s * (MB * rc), det);
		gA = MA * x;
		lamA = Dot(x, gA);
		lamB = Quad(MB, x - rc);
		usable = det > 0.0 && std::isfinite(lamB);
		level = (1.0 - s) * lamA + s * lamB;
		point = pa.p + x;
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
	}
	if (!usable || !IsFinite(x) || !std::isfinite(lamA) || !(LengthSquared(gA) > 0.0))
	{
		r.failure = "ellipse pair: non-finite answer";
		return r;
	}
	r.status = SolveStatus::converged;
	r.level = level;
	r.point = point;
	r.normal = Normalize(gA);
	r.multiplier = s / (1.0 - s);
	return r;
}

} // namespace b2a
