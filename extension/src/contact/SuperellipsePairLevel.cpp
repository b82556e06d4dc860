// b2analytic: the common level of two superellipses by Newton, the levels evaluated inline.
#include "contact/SolverCore.h"
#include "contact/WarmSlide.h"

#include "b2analytic/SuperellipseShape.h"
#include "geometry/SuperellipseTerms.h"
#include "numerics/CodeLayout.h"
#include "numerics/SmallLinear.h"

#include <algorithm>
#include <cmath>

namespace b2a
{

namespace
{
// One shape's gauge ψ = f^{1/q} at a point, with ∇ψ and ∇²ψ in A's body frame and units of the
// pair's size, and f and ∇f there (the contact's line crossings start from them). Plain doubles
// without initialisers: every evaluation fills them all.
struct Gauge
{
	double lambda, psi;
	double gx, gy;          // ∇ψ
	double hxx, hxy, hyy;   // ∇²ψ
	double fx, fy;          // ∇f
};

// The pair seen from A: lengths in units of the pair's size s = (rA + rB)/2, the frame A's body
// frame with its origin at A's centre. B's centre lies at c and B's body axes are turned by r.
struct PairInA
{
	SuperellipseTerms a, b; // the shapes' terms in units of s (ScaledTerms)
	Vec2 c;
	Rot r;
	double q = 1.0, invQ = 1.0; // the gauge's power (PairFrame::power) and its inverse
	bool integer = false;       // IntegerExponents for both shapes
	bool log = false;           // the gauge ψ = log f instead (SolveSuperellipsePairLevelChecked)
	bool evaluatedExit = false; // the last step evaluated, not taken to first order (the same)
};

// ψ = f^{1/q}: ∇ψ = ψ'∇f, ∇²ψ = ψ'∇²f + ψ''∇f∇fᵀ with ψ' = ψ/(qf), ψ'' = ψ'(1/q − 1)/f (the
// generic solver's PairFrame::Eval), from f, ∇f and ∇²f already in A's frame. At the centre
// (f = 0) ψ and its derivatives vanish and the Newton step fails, as it should.
inline void ToGauge(const PairInA& p, double f, double fx, double fy, double hxx, double hxy, double hyy, Gauge& g)
{
	g.lambda = f;
	g.fx = fx;
	g.fy = fy;
	if (p.log)
	{
		// ψ = log f: ∇ψ = ∇f/f, ∇²ψ = ∇²f/f − ∇f∇fᵀ/f² (log 0 = −∞: the residual turns NaN).
		const double inv = 1.0 / f;
		g.psi = std::log(f);
		g.gx = inv * fx;
		g.gy = inv * fy;
		g.hxx = inv * hxx - g.gx * g.gx;
		g.hxy = inv * hxy - g.gx * g.gy;
		g.hyy = inv * hyy - g.gy * g.gy;
		return;
	}
	if (p.q == 1.0)
	{
		g.psi = f;
		g.gx = fx;
		g.gy = fy;
		g.hxx = hxx;
		g.hxy = hxy;
		g.hyy = hyy;
		return;
	}
	const double psi = f > 0.0 ? RootOf(f, p.q) : 0.0;
	const double inv = f > 0.0 ? 1.0 / f : 0.0;
	const double d1 = psi * p.invQ * inv;
	const double d2 = d1 * (p.invQ - 1.0) * inv;
	g.psi = psi;
	g.gx = d1 * fx;
	g.gy = d1 * fy;
	g.hxx = d1 * hxx + d2 * fx * fx;
	g.hxy = d1 * hxy + d2 * fx * fy;
	g.hyy = d1 * hyy + d2 * fy * fy;
}

// f, ∇f and ∇²f's diagonal in the shape's axes: IntegerSuperellipseDerivatives where both
// shapes' exponents are integers ≥ 2, else SmoothSuperellipseDerivatives (every exponent ≥ 2
// here: RawSuperellipseDerivatives' values without its cases for exponents below 2).
inline AxisDerivatives AxisDerivativesAt(const SuperellipseTerms& t, Vec2 x, bool integer)
{
	if (integer)
		return IntegerSuperellipseDerivatives(t, x.x, x.y);
	return SmoothSuperellipseDerivatives(t, x.x, x.y);
}

// Both shapes at ξ (A's frame, units of s). A's derivatives are already in its frame; B's are
// turned by r: ∇f ↦ R∇f and the diagonal ∇²f = diag(hx, hy) ↦ R diag(hx, hy) Rᵀ.
inline void Evaluate(const PairInA& p, Vec2 xi, Gauge& ga, Gauge& gb)
{
	const AxisDerivatives da = AxisDerivativesAt(p.a, xi, p.integer);
	ToGauge(p, da.f, da.gx, da.gy, da.hx, 0.0, da.hy, ga);
	const AxisDerivatives db = AxisDerivativesAt(p.b, InvRotate(p.r, xi - p.c), p.integer);
	const double c = p.r.c, s = p.r.s, hx = db.hx, hy = db.hy;
	const Vec2 grad = Rotate(p.r, Vec2(db.gx, db.gy));
	ToGauge(p, db.f, grad.x, grad.y, c * c * hx + s * s * hy, c * s * (hx - hy), s * s * hx + c * c * hy, gb);
}

// The residual (∇ψA + μ∇ψB, ψA − ψB) and the square of its size relative to the size of its
// terms (the generic solver's measure, squared, so that both accept the same rounding floor: the
// thresholds below are the generic solver's, squared). The square root would be on every
// evaluation for nothing but these comparisons.
// A NaN anywhere in the gauges' values or gradients makes it NaN.
inline double LevelScale(const PairInA& p, const Gauge& ga, const Gauge& gb)
{
	// ψA − ψB relative to the gauges, or for ψ = log f as it is (a relative difference of f).
	return p.log ? 1.0 : ga.psi * ga.psi + gb.psi * gb.psi + 1e-300;
}
inline double Residual(const PairInA& p, const Gauge& ga, const Gauge& gb, double mu, double r[3])
{
	r[0] = ga.gx + mu * gb.gx;
	r[1] = ga.gy + mu * gb.gy;
	r[2] = ga.psi - gb.psi;
	const double gradScale = ga.gx * ga.gx + ga.gy * ga.gy + mu * mu * (gb.gx * gb.gx + gb.gy * gb.gy) + 1e-300;
	const double levelScale = LevelScale(p, ga, gb);
	return (r[0] * r[0] + r[1] * r[1]) / gradScale + r[2] * r[2] / levelScale;
}

// The cold start: the point of the centre line ξ = t·c where both levels agree (the generic
// solver's GeometricStart, in closed form along the line). Along it each level is a sum of two
// powers, fA = αx·t^nA + αy·t^mA with α = |c·(1/a, 1/b)|^(n, m), and fB the same in 1 − t with
// B's exponents and e = Rᵀc: fA rises from 0 and fB falls to 0, so h = fA^{1/p} − fB^{1/p} has
// one root in (0, 1). With p the smallest exponent (taken down to 2, 4 or 8, for square
// roots) each f^{1/p} is nearly linear in t, exactly so when the exponents are all equal,
// where Newton lands on the root in one step; a bracket that bisection keeps catches the rest.
// False when the levels vanish (coincident centres).
bool CentreLineStart(const PairInA& p, double& t)
{
	const SuperellipseTerms &a = p.a, &b = p.b;
	const Vec2 e = InvRotate(p.r, p.c);
	const double ax = PowAbs(p.c.x * a.invA, a.n, a.nInt), ay = PowAbs(p.c.y * a.invB, a.m, a.mInt);
	const double bx = PowAbs(e.x * b.invA, b.n, b.nInt), by = PowAbs(e.y * b.invB, b.m, b.mInt);
	if (!(ax + ay > 0.0) || !(bx + by > 0.0) || !std::isfinite(ax + ay + bx + by))
		return false;
	const double lowest = std::min(std::min(a.n, a.m), std::min(b.n, b.m));
	const double root = lowest >= 8.0 ? 8.0 : (lowest >= 4.0 ? 4.0 : 2.0);
	// f(s) = αx·s^n + αy·s^m, its p-th root r and dr/ds = r·f'/(p·f).
	auto side = [&](const SuperellipseTerms& k, double wx, double wy, double at, double& slope) {
		const double sn = PowAbs(at, k.n, k.nInt), sm = PowAbs(at, k.m, k.mInt);
		const double f = wx * sn + wy * sm;
		const double r = RootOf(f, root);
		slope = f > 0.0 ? r * (k.n * wx * sn + k.m * wy * sm) / (at * root * f) : 0.0;
		return r;
	};
	double lo = 0.0, hi = 1.0;
	t = 0.5;
	for (int it = 0; it < 60; ++it)
	{
		double slopeA = 0.0, slopeB = 0.0;
		const double h = side(a, ax, ay, t, slopeA) - side(b, bx, by, 1.0 - t, slopeB);
		if (!std::isfinite(h))
			return false;
		if (h == 0.0)
			return true;
		(h < 0.0 ? lo : hi) = t;
		const double slope = slopeA + slopeB;
		double next = slope > 0.0 ? t - h / slope : 0.5 * (lo + hi);
		if (!(next > lo && next < hi))
			next = 0.5 * (lo + hi);
		const double moved = std::fabs(next - t);
		t = next;
		if (moved <= 1e-12 || hi - lo <= 1e-12)
			return true;
	}
	return true; // a start, not an answer: the bracket is narrow by now
}

// A start for the point of the superellipse with terms t (integer exponents ≥ 3, in the pair's
// units; a and b its semi-axes there) whose normal is along d: SupportNear(d, 0) with RootGuess's
// roots (SupportNear's CubeRoot for n = 4, pow for n = 8, exp and log for n ≠ m are a visible
// part of a cold contact). With e = (a·dx, b·dy) and κ = max(|ex|/n, |ey|/m), the point of the bounding
// box's side where the level curve's normal is along d is X = (|ex|/(nκ))^{1/(n−1)},
// Y = (|ey|/(mκ))^{1/(m−1)} (Lagrange's condition with one of X, Y equal to 1). |ex|/n =
// |dx|/gradX, so the ratio of the two is |dy|·gradX/(|dx|·gradY): one division. The point lies on
// a level f ∈ [1, 2] outside the surface, also for n = m, where scaling it onto the surface
// (f^{−1/n}: the support point itself) cost a chain of roots and a division, and gave a worse
// start (see BoxStart).
Vec2 StartSupport(const SuperellipseTerms& t, double a, double b, Vec2 d)
{
	const double px = std::fabs(d.x) * t.gradY, py = std::fabs(d.y) * t.gradX;
	double X = 1.0, Y = 1.0;
	if (px >= py)
		Y = RootGuess(py / px, t.mInt - 1);
	else
		X = RootGuess(px / py, t.nInt - 1);
	return Vec2(a * std::copysign(X, d.x), b * std::copysign(Y, d.y));
}

// The cold start of blocky pairs (Blocky: every exponent at least 3): the contact of the bounding
// boxes. Scaled about their centres by s, two boxes touch where s first reaches the largest, over
// the four face normals u of the two boxes, of |c·u| / (hA(u) + hB(u)), h the box's half-width
// along u (the separating-axis test, solved for the scale). If u is a face normal of A, B's point
// that touches it is B's support point against u (SuperellipseShape::Support in closed form for
// n = m; for n ≠ m, and for integer exponents, the point of B's box side with its normal along u,
// below), scaled by s about B's centre, and the other way round for a face of B. Blocky
// superellipses are nearly their boxes, and a corner meeting a face is the common contact: from
// there Newton needs fewer iterations than from the centre line, for equal and for mixed
// exponents (and where it does not, the centre line's own root search is dearer than the box's
// supports). For rounder shapes, an ellipse among them, the centre line is the better start.
bool BoxStart(const SuperellipseShape& a, const SuperellipseShape& b, double size, const PairInA& p, Vec2& xi)
{
	const double aA = 1.0 / p.a.invA, bA = 1.0 / p.a.invB, aB = 1.0 / p.b.invA, bB = 1.0 / p.b.invB;
	const Vec2 bx(p.r.c, p.r.s), by(-p.r.s, p.r.c);
	const Vec2 axes[4] = {Vec2(1.0, 0.0), Vec2(0.0, 1.0), bx, by};
	double scale = -1.0;
	int face = 0;
	for (int i = 0; i < 4; ++i)
	{
		const Vec2 u = axes[i];
		const double widths = aA * std::fabs(u.x) + bA * std::fabs(u.y) + aB * std::fabs(Dot(u, bx)) + bB * std::fabs(Dot(u, by));
		const double s = std::fabs(Dot(p.c, u)) / widths;
		if (s > scale)
		{
			scale = s;
			face = i;
		}
	}
	const Vec2 u = Dot(p.c, axes[face]) < 0.0 ? -axes[face] : axes[face]; // from A towards B
	const double k = scale / size; // the support points are in body units, ξ in the pair's
	// For n ≠ m, not the support point itself but SupportNear's start for it: the point on the side
	// of the bounding box where the level curve's normal is along the direction, no Newton step. As
	// a start it is at least as good as the exact support, or steps towards it, and cheaper.
	// Integer exponents take StartSupport, SupportNear(d, 0) with guessed roots, cheaper still at
	// the same Newton iterations. It takes the box side's point for n = m too. That point errs the
	// right way: the boxes touch at the scale s, the particles inside them only at a common level
	// above s, so the common point lies beyond B's surface scaled by s, where the box side's point
	// is. Scaling it onto the surface (the support point) costs a chain of two or three square
	// roots and a division, and Newton needs more steps from there.
	if (p.integer)
		xi = face < 2 ? p.c + scale * Rotate(p.r, StartSupport(p.b, aB, bB, InvRotate(p.r, -u))) : scale * StartSupport(p.a, aA, bA, u);
	else
		xi = face < 2 ? p.c + k * Rotate(p.r, b.SupportNear(InvRotate(p.r, -u), 0)) : k * a.SupportNear(u, 0);
	return scale > 0.0 && IsFinite(xi);
}

// Whether BoxStart is the better start for the pair: every exponent at least 3 (the shapes
// close to their boxes).
bool Blocky(const PairInA& p) { return std::min(std::min(p.a.n, p.a.m), std::min(p.b.n, p.b.m)) >= 3.0; }

// The pair seen from A (PairInA) for a solve.
PairInA PairOf(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb, double size, bool log,
               bool evaluatedExit)
{
	PairInA p;
	p.a = ScaledTerms(a.Terms(), size);
	p.b = ScaledTerms(b.Terms(), size);
	const Pose rel = Relative(pa, pb);
	p.c = rel.p / size;
	p.r = rel.q;
	p.q = std::min(a.LevelPower(), b.LevelPower());
	p.invQ = 1.0 / p.q;
	p.integer = IntegerExponents(p.a) && IntegerExponents(p.b);
	p.log = log;
	p.evaluatedExit = evaluatedExit;
	return p;
}

// The start: where the warm start's point went with both bodies' motions and the slide along the
// surfaces, with its multiplier; cold, the boxes' contact (Blocky pairs) or the centre line's
// point of equal levels, with μ = 0 (to be balanced from the gradients there). False where the
// levels along the centre line vanish (coincident centres).
bool StartOf(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb, double size,
             const PairInA& p, const WarmStart* warm, Vec2& xi, double& mu)
{
	if (warm && warm->valid && warm->multiplier > 0.0 && IsFinite(warm->localPoint) && std::isfinite(warm->multiplier))
	{
		mu = warm->multiplier;
		xi = WarmStartPoint(*warm, pa, pb, size) / size;
		return true;
	}
	mu = 0.0;
	if (Blocky(p) && BoxStart(a, b, size, p, xi))
		return true;
	double t = 0.5;
	if (!CentreLineStart(p, t))
		return false;
	xi = t * p.c;
	return true;
}

// An evaluated point of the solve.
struct Point
{
	Vec2 xi;
	double mu;
	Gauge A, B;
	double r[3];
	double relativeSquared; // NaN where anything evaluated was not finite
};

B2A_FORCE_INLINE inline void EvaluateAt(const PairInA& p, Point& q, Vec2 xi, double mu)
{
	q.xi = xi;
	q.mu = mu;
	Evaluate(p, xi, q.A, q.B);
	q.relativeSquared = Residual(p, q.A, q.B, mu, q.r);
}

// A cold start's point, with μ balancing the gradients there, |∇ψA|/|∇ψB| (GeometricStart's).
void EvaluateColdStart(const PairInA& p, Point& q, Vec2 xi)
{
	q.xi = xi;
	Evaluate(p, xi, q.A, q.B);
	const double ga = std::sqrt(q.A.gx * q.A.gx + q.A.gy * q.A.gy);
	const double gb = std::sqrt(q.B.gx * q.B.gx + q.B.gy * q.B.gy);
	q.mu = ga > 0.0 && gb > 0.0 && std::isfinite(ga / gb) ? ga / gb : 1.0;
	q.relativeSquared = Residual(p, q.A, q.B, q.mu, q.r);
}

// The least-squares multiplier for a warm start's point, μ = −∇ψA·∇ψB / |∇ψB|², where it lowers
// the residual (a stale multiplier makes Newton crawl). Not after a cold start: there it never
// does. With c = −cos∠(∇ψA, ∇ψB) ∈ (0, 1] (μ > 0 needs it), the gradient part of the relative
// residual is (1 − c²)/(1 + c²) at the least-squares μ and 1 − c at |∇ψA|/|∇ψB|, and
// (1 + c)/(1 + c²) ≥ 1; the level part does not depend on μ.
void TakeLeastSquaresMultiplier(const PairInA& p, Point& q)
{
	const double gb2 = q.B.gx * q.B.gx + q.B.gy * q.B.gy;
	const double muLs = gb2 > 0.0 ? -(q.A.gx * q.B.gx + q.A.gy * q.B.gy) / gb2 : 0.0;
	if (muLs > 0.0 && std::isfinite(muLs) && muLs != q.mu)
	{
		double r[3];
		const double relativeSquared = Residual(p, q.A, q.B, muLs, r);
		if (relativeSquared < q.relativeSquared)
		{
			q.mu = muLs;
			q.relativeSquared = relativeSquared;
			std::copy(r, r + 3, q.r);
		}
	}
}

// The last step, taken without evaluating the shapes again: ψ + ∇ψ·δ, ∇ψ + ∇²ψ·δ, f = ψ^q
// (df = q·f·dψ/ψ) and ∇f = (q·f/ψ)∇ψ, exact to O(|δ|²).
void TakeUnevaluatedStep(const PairInA& p, Point& q, const double delta[3])
{
	const double dx = delta[0], dy = delta[1];
	q.xi = q.xi + Vec2(dx, dy);
	q.mu += delta[2];
	for (Gauge* g : {&q.A, &q.B})
	{
		const double dpsi = g->gx * dx + g->gy * dy;
		g->gx += g->hxx * dx + g->hxy * dy;
		g->gy += g->hxy * dx + g->hyy * dy;
		if (p.log)
		{
			g->lambda += g->lambda * dpsi; // dλ = λ·dψ
			g->fx = g->lambda * g->gx;
			g->fy = g->lambda * g->gy;
		}
		else if (g->psi > 0.0)
		{
			g->lambda += p.q * g->lambda * dpsi / g->psi;
			const double k = p.q * g->lambda / (g->psi + dpsi);
			g->fx = k * g->gx;
			g->fy = k * g->gy;
		}
		g->psi += dpsi;
	}
}

// Backtracking on the residual along δ with row weights frozen at q (the generic solver's
// LineSearch): the first of α = 1, ½, ¼, … that lowers the merit enough, evaluated into `trial`.
bool LineSearch(const PairInA& p, const Point& q, const double delta[3], Point& trial, double& alpha)
{
	const double w12 = 1.0 / (q.A.gx * q.A.gx + q.A.gy * q.A.gy + q.mu * q.mu * (q.B.gx * q.B.gx + q.B.gy * q.B.gy) + 1e-300);
	const double w3 = 1.0 / LevelScale(p, q.A, q.B);
	auto merit = [&](const Point& t) { return w12 * (t.r[0] * t.r[0] + t.r[1] * t.r[1]) + w3 * t.r[2] * t.r[2]; };
	const double merit0 = merit(q);
	const int halvings = q.relativeSquared < 1e-9 * 1e-9 ? 3 : 40;
	alpha = 1.0;
	for (int k = 0; k < halvings; ++k, alpha *= 0.5)
	{
		EvaluateAt(p, trial, q.xi + alpha * Vec2(delta[0], delta[1]), q.mu + alpha * delta[2]);
		if (trial.mu > 0.0 && merit(trial) <= (1.0 - 1e-4 * alpha) * merit0) // (false for NaN)
			return true;
	}
	return false;
}

// How far an evaluated point is from solving the conditions (ResidualOfConditions). A is
// evaluated at ξ itself, in its own body frame, each axis apart (its terms |ξx/a|^n and
// |ξy/b|^m and their derivatives to a few parts in 1e16 of themselves, whatever the size of ξ):
// its floors are those few parts alone. B's body coordinates there, ξ − c turned, are rounded to
// a part in 1e16 of the larger of |ξ| and |c| (c itself, the centres' difference, is the input's,
// as the reference takes it). The world coordinates do not enter: a needle crossing another deep
// inside it at a level of 1e-30 has a level set 1e-15 of its size thick, which world
// coordinates of 1e3 sizes cannot hold and A's frame does.
double RoundingOfB(const PairInA& p, const Point& q)
{
	return std::numeric_limits<double>::epsilon() * std::max(Length(q.xi), Length(p.c));
}
// With ψ = log f the levels f themselves, with ∇f = f∇ψ and f∇²ψ (whose curvatures across the
// gradient, tᵀ∇²t/|∇|, are the gauge's).
ConditionsResidual ResidualAt(const PairInA& p, const Point& q)
{
	const double ka = p.log ? q.A.lambda : 1.0, kb = p.log ? q.B.lambda : 1.0;
	return ResidualOfConditions(p.log ? ka : q.A.psi, p.log ? kb : q.B.psi, ka * Vec2(q.A.gx, q.A.gy), kb * Vec2(q.B.gx, q.B.gy),
	                            ka * Sym22{q.A.hxx, q.A.hxy, q.A.hyy}, kb * Sym22{q.B.hxx, q.B.hxy, q.B.hyy}, 0.0,
	                            RoundingOfB(p, q));
}

// Whether an evaluated point solves the conditions to what double precision allows
// (ConditionsHold's standard).
bool Solved(const PairInA& p, const Point& q)
{
	const double levelA = p.log ? q.A.lambda : q.A.psi, levelB = p.log ? q.B.lambda : q.B.psi;
	if (ConditionsWithin(levelA, levelB, Vec2(q.A.gx, q.A.gy), Vec2(q.B.gx, q.B.gy), 1e-11, 1e-11))
		return true; // (the common case, before the roots of the reach)
	return ResidualAt(p, q).Within(1e-11, 1e-10, p.log ? 1.0 : p.q);
}

// The answer at the solved point q (opposed gradients and a positive multiplier, else the
// failure), and what the contact needs from it in `at`.
LevelResult Answer(const PairInA& p, const Pose& pa, double size, const Point& q, const WarmStart* warm,
                   SuperellipsePairPoint* at, LevelResult result)
{
	const Vec2 nA = Normalize(Vec2(q.A.gx, q.A.gy)), nB = Normalize(Vec2(q.B.gx, q.B.gy));
	if (!(Dot(nA, nB) < -1.0 + 1e-6))
	{
		result.failure = "converged to a point where the gradients are not opposed";
		return result;
	}
	// Every exit (a step below the tolerance, a residual below 1e-15 of its scale, the last step
	// taken unevaluated, a singular Jacobian at rounding level) promises a solution only where
	// the conditions hold at the point (Solved): deep inside each other, needles' gauges agree to
	// 1e-11 while their normals are 0.01 to 2 rad apart, and the contact's normal is their mean.
	// There the point's rounding alone turns the normals by 1e3 rad or more (RoundingKeepsNormals,
	// with A's point exact in its frame and B's rounded as ResidualAt says), and agreement in
	// double says nothing.
	const double roundingB = RoundingOfB(p, q);
	if (!Solved(p, q) ||
	    !RoundingKeepsNormals(Vec2(q.A.gx, q.A.gy), Vec2(q.B.gx, q.B.gy), Sym22{q.A.hxx, q.A.hxy, q.A.hyy},
	                          Sym22{q.B.hxx, q.B.hxy, q.B.hyy}, 0.0, roundingB * roundingB))
	{
		result.failure = "stopped short of a solution (its levels or normals disagree beyond rounding)";
		return result;
	}
	if (!(q.mu > 0.0))
	{
		result.failure = "converged to a non-positive multiplier";
		return result;
	}
	result.status = SolveStatus::converged;
	result.failure = "";
	result.level = q.A.lambda;
	result.point = ToWorld(pa, size * q.xi);
	result.normal = Normalize(Rotate(pa.q, nA)); // unit even where pa.q is not quite (float poses)
	result.multiplier = q.mu;
	if (at)
	{
		at->slide.valid = false;
		if (warm) // only a caller that keeps a warm start needs it
			ComputeSlide(Vec2(q.A.gx, q.A.gy), Sym22{q.A.hxx, q.A.hxy, q.A.hyy}, Sym22{q.B.hxx, q.B.hxy, q.B.hyy}, nA, q.mu,
			             size, pa.q, at->slide);
		at->gradA = Rotate(pa.q, Vec2(q.A.fx, q.A.fy)) / size;
		at->gradB = Rotate(pa.q, Vec2(q.B.fx, q.B.fy)) / size;
		at->levelA = q.A.lambda;
		at->levelB = q.B.lambda;
		at->valid = IsFinite(at->gradA) && IsFinite(at->gradB);
	}
	return result;
}
} // namespace

namespace
{
LevelResult Solve(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                  const SolverOptions& options, const WarmStart* warm, SuperellipsePairPoint* at, SuperellipseHandOver* handOver,
                  bool log, bool evaluatedExit)
{
	// The generic Newton (CommonLevelNewton.cpp: the same equations, gauge, trust region, line
	// search and stopping rules) without what it pays for being generic: the shapes are evaluated
	// inline from their terms, in A's body frame (A's point needs no transform, B's one rotation),
	// the multiplier is μ itself rather than log μ (no exp per evaluation; steps are limited to
	// the same factor e² either way), and the answer keeps what the contact's normal and points
	// need. Its warm starts and multipliers are interchangeable with the generic solver's.
	if (at)
		at->valid = false;
	if (handOver)
		handOver->taken = false;
	LevelResult result;
	result.method = SolveMethod::newton;
	const double size = 0.5 * (a.BoundingRadius() + b.BoundingRadius());
	const PairInA p = PairOf(a, pa, b, pb, size, log, evaluatedExit);
	Vec2 xi;
	double mu = 1.0;
	if (!StartOf(a, pa, b, pb, size, p, warm, xi, mu))
	{
		result.failure = "coincident centres: no common-level point between them";
		return result;
	}
	// Two evaluated points, the current one and the trial, swapped when a trial is accepted.
	Point points[2];
	Point* current = &points[0];
	Point* trial = &points[1];
	const bool cold = mu == 0.0;
	if (cold)
		EvaluateColdStart(p, *current, xi);
	else
		EvaluateAt(p, *current, xi, mu);
	const double trust = std::max(0.5, 0.5 * Length(p.c));
	const int cap = std::max(1, options.maxIterations);
	double previousXi = 0.0, previousMu = 0.0; // the last full step's size in ξ and in μ/μ (0: none yet)
	int forced = 0;                           // full steps taken where the line search stalled
	for (int it = 1; it <= cap; ++it)
	{
		Point& q = *current;
		result.iterations = it;
		if (!std::isfinite(q.relativeSquared))
		{
			result.failure = "non-finite level value or derivative during Newton iteration";
			return result;
		}
		if (it == 1 && !cold)
			TakeLeastSquaresMultiplier(p, q);
		// Jacobian of (∇ψA + μ∇ψB, ψA − ψB) with respect to (ξ, μ): [[H, ∇ψB], [(∇ψA − ∇ψB)ᵀ, 0]]
		// with H = ∇²ψA + μ∇²ψB. (A Hessian that is not finite makes it singular to the solve.)
		const double hxx = q.A.hxx + q.mu * q.B.hxx, hxy = q.A.hxy + q.mu * q.B.hxy, hyy = q.A.hyy + q.mu * q.B.hyy;
		const double minusR[3] = {-q.r[0], -q.r[1], -q.r[2]};
		const double dx = q.A.gx - q.B.gx, dy = q.A.gy - q.B.gy;
		const Solve3Result step = SolveBordered(hxx, hxy, hyy, q.B.gx, q.B.gy, dx, dy, minusR);
		// (On log f, whose gradients' units differ by the needles' thicknesses, 1e-14 to 1e3 at
		// levels of 1e-23, J's condition number is ~1e-38 where the step is right: any finite
		// step goes to the line search, which holds it to lowering the residual.)
		const bool finiteStep = p.log && step.rcond > 0.0 && std::isfinite(step.x[0] + step.x[1] + step.x[2]);
		if (!finiteStep && !BorderedStepUsable(step.rcond, hxx, hxy, hyy, q.B.gx, q.B.gy, dx, dy))
		{
			if (q.relativeSquared < 1e-11 * 1e-11 || Solved(p, q))
				break; // solved: the Jacobian is singular only at the answer's rounding level
			result.failure = "singular or ill-conditioned Jacobian";
			return result;
		}
		double delta[3] = {step.x[0], step.x[1], step.x[2]};
		// Quadratic convergence: after a full step δₖ, the new step δₖ₊₁ gives Newton's constant
		// K ≈ |δₖ₊₁|/|δₖ|², and the error left after taking δₖ₊₁ is about K·|δₖ₊₁|². Where that is
		// ten times below the tolerance, δₖ₊₁ is the last step and is taken without evaluating
		// the shapes again (TakeUnevaluatedStep; the generic solver decides this one evaluation
		// later, from the accepted step). The estimate holds only once Newton is in its quadratic
		// regime, so it needs the evidence of it: the residual already small (1e-6), the previous
		// step small (1e-2 of the size), and both the point's steps and the multiplier's relative
		// steps contracting by 4 or more, each with its own K (a point that has settled while μ
		// still moves, or the reverse, has not converged).
		const double stepXi = std::max(std::fabs(delta[0]), std::fabs(delta[1]));
		const double stepMu = std::fabs(delta[2]) / q.mu;
		auto settled = [&](double now, double before) {
			return now <= 0.1 * options.stepTolerance ||
			       (before > 0.0 && now < 0.25 * before && 10.0 * (now / (before * before)) * now * now <= options.stepTolerance);
		};
		if (q.relativeSquared <= 1e-6 * 1e-6 && previousXi > 0.0 && previousXi <= 1e-2 && settled(stepXi, previousXi) &&
		    settled(stepMu, previousMu))
		{
			if (p.evaluatedExit)
			{
				// At a needle's tip the gradient turns over 1e-24 of the size: to first order
				// its last step may leave the normals 1e-3 rad from where the point puts them.
				EvaluateAt(p, *trial, q.xi + Vec2(delta[0], delta[1]), q.mu + delta[2]);
				std::swap(current, trial);
			}
			else
				TakeUnevaluatedStep(p, q, delta);
			break;
		}
		// Trust region (the generic solver's): at most half the pair's size or of the distance
		// between the centres in ξ, and a factor e² in μ.
		double limit = 1.0;
		if (stepXi > trust) limit = trust / stepXi;
		const double up = 6.38905609893065 * q.mu, down = -0.864664716763387 * q.mu; // (e² − 1)μ, (e⁻² − 1)μ
		if (delta[2] > up) limit = std::min(limit, up / delta[2]);
		if (delta[2] < down) limit = std::min(limit, down / delta[2]);
		if (handOver && limit == 1.0 && stepXi <= handOver->below && q.mu + delta[2] > 0.0)
		{
			// Within Newton's quadratic regime: the caller takes this step and finishes on the raw
			// levels. The step is handed over unevaluated: the finish evaluates its end anyway, and
			// its own tests (a first step within 5 % of the size, steps contracting as Newton's do,
			// the conditions at its end) turn a step that was not in the regime into a full solve.
			handOver->point = size * (q.xi + Vec2(delta[0], delta[1]));
			handOver->multiplier = q.mu + delta[2];
			handOver->iterations = it;
			handOver->taken = true;
			result.failure = "handed over to FinishSuperellipseContact";
			return result;
		}
		for (double& d : delta)
			d *= limit;
		double alpha = 1.0;
		if (!LineSearch(p, q, delta, *trial, alpha))
		{
			if (Solved(p, q))
				break; // rounding floor
			// Near the solution the full step, as the generic solver takes it.
			if (!(forced < 2 && ResidualAt(p, q).Within(1e-4, 1e-4, p.q)))
			{
				result.failure = "line search stalled (no step lowers the residual)";
				return result;
			}
			++forced;
			alpha = 1.0;
			EvaluateAt(p, *trial, q.xi + Vec2(delta[0], delta[1]), q.mu + delta[2]);
		}
		const double moved = alpha * limit * stepXi;
		std::swap(current, trial);
		const bool full = limit == 1.0 && alpha == 1.0;
		// A step below the tolerance ends the solve only at a solution (the generic solver's rule).
		if ((full && moved <= options.stepTolerance && Solved(p, *current)) ||
		    current->relativeSquared < 1e-15 * 1e-15)
			break;
		previousXi = full ? stepXi : 0.0;
		previousMu = full ? stepMu : 0.0;
		if (it == cap)
		{
			result.failure = "iteration cap reached";
			return result;
		}
	}
	return Answer(p, pa, size, *current, warm, at, result);
}
} // namespace

LevelResult SolveSuperellipsePairLevel(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                       const SolverOptions& options, const WarmStart* warm, SuperellipsePairPoint* at,
                                       SuperellipseHandOver* handOver)
{
	return Solve(a, pa, b, pb, options, warm, at, handOver, false, false);
}

LevelResult SolveSuperellipsePairLevelChecked(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                              const SolverOptions& options, const WarmStart* warm, bool logLevels)
{
	return Solve(a, pa, b, pb, options, warm, nullptr, nullptr, logLevels, true);
}

} // namespace b2a
