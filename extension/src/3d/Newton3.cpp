// b2analytic: Newton–Raphson on the 3D common level (four unknowns), with step control.
#include "3d/Solvers3.h"

#include "numerics/RootFinding.h"
#include "numerics/Solve4.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace b2a
{

namespace
{
// A residual (relative to its terms) below which a stalled or singular Newton iteration is at
// its rounding floor and has converged, where the point's own rounding does not set a higher one
// (RoundingFloor). Above it the solve fails (the chain's min-max takes over): flat faces of high
// exponents touching face to face stall Newton at residuals of 1e-10, where the two levels still
// differ by that much.
constexpr double kRoundingFloor = 1e-12;

struct NewtonPoint3
{
	Vec3 xi;
	double nu = 0.0;
	double mu = 1.0; // e^ν
	GaugeValue3 A, B;
	double r[4] = {0.0, 0.0, 0.0, 0.0};
	double relative = 0.0; // residual relative to the size of its terms
	bool finite = false;
};

// The largest absolute row sum of a symmetric matrix (a bound on its eigenvalues).
double RowSumNorm(const Sym33& h)
{
	return std::max({std::fabs(h.xx) + std::fabs(h.xy) + std::fabs(h.xz), std::fabs(h.xy) + std::fabs(h.yy) + std::fabs(h.yz),
	                 std::fabs(h.xz) + std::fabs(h.yz) + std::fabs(h.zz)});
}

// The relative residual that rounding the point alone produces (the 2D ResidualOfConditions'
// floors): the body coordinates are formed from world points as large as `reach`, so ξ is known
// to δ = ε·reach / scale, within which the residual's rows move by (‖H_A‖ + μ‖H_B‖)δ (gradients)
// and (|∇ψA| + |∇ψB|)δ (levels). Where a level set is thin across the frame's scale (a plate or
// needle at a low level: a normalised thickness of 1e-4) its Hessian is 1e4 times its gradient
// and this floor 1e-11, above kRoundingFloor: no step lowers the residual below it, and a point
// there solves the conditions to rounding (the normals opposed to about the floor, in radians).
double RoundingFloor(const PairFrame3& f, const NewtonPoint3& p)
{
	const double reach = std::max({Length(f.World(p.xi)), Length(f.a.pose.p), Length(f.b.pose.p)});
	const double delta = std::numeric_limits<double>::epsilon() * reach / f.scale;
	const double gradNoise = delta * (RowSumNorm(p.A.hess) + p.mu * RowSumNorm(p.B.hess));
	const double levelNoise = delta * (Length(p.A.grad) + Length(p.B.grad));
	const double gradScale = LengthSquared(p.A.grad) + p.mu * p.mu * LengthSquared(p.B.grad) + 1e-300;
	const double levelScale = p.A.psi * p.A.psi + p.B.psi * p.B.psi + 1e-300;
	const double floor = std::sqrt(gradNoise * gradNoise / gradScale + levelNoise * levelNoise / levelScale);
	return std::isfinite(floor) ? std::max(kRoundingFloor, floor) : kRoundingFloor;
}

// The residual for multiplier μ at an evaluated point: fills r and returns its size relative to
// its terms.
double Residual(const NewtonPoint3& p, double mu, double r[4])
{
	const Vec3 g = p.A.grad + mu * p.B.grad;
	r[0] = g.x;
	r[1] = g.y;
	r[2] = g.z;
	r[3] = p.A.psi - p.B.psi;
	const double gradScale = LengthSquared(p.A.grad) + mu * mu * LengthSquared(p.B.grad) + 1e-300;
	const double levelScale = p.A.psi * p.A.psi + p.B.psi * p.B.psi + 1e-300;
	return std::sqrt(LengthSquared(g) / gradScale + r[3] * r[3] / levelScale);
}

void SetMultiplier(NewtonPoint3& p, double nu, double mu)
{
	p.nu = nu;
	p.mu = mu;
	p.relative = Residual(p, mu, p.r);
	p.finite = p.A.finite && p.B.finite && std::isfinite(mu) && std::isfinite(p.relative);
}

void Evaluate(const PairFrame3& f, Vec3 xi, double nu, NewtonPoint3& p)
{
	p.xi = xi;
	p.A = f.Eval(f.a, xi, true);
	p.B = f.Eval(f.b, xi, true);
	SetMultiplier(p, nu, std::exp(nu));
}

// μ = −∇ψA·∇ψB / |∇ψB|², the least-squares multiplier at the point, where it lowers the residual
// (a stale multiplier makes Newton crawl).
void TakeLeastSquaresMultiplier(NewtonPoint3& p)
{
	const double gb2 = LengthSquared(p.B.grad);
	const double muLs = gb2 > 0.0 ? -Dot(p.A.grad, p.B.grad) / gb2 : 0.0;
	const double nuLs = muLs > 0.0 ? std::log(muLs) : p.nu;
	if (nuLs == p.nu || !std::isfinite(nuLs))
		return;
	double r[4];
	const double relative = Residual(p, muLs, r);
	if (std::isfinite(relative) && relative < p.relative)
		SetMultiplier(p, nuLs, muLs);
}

// The Newton step: J = [[H_A + μH_B, μ∇ψB], [(∇ψA − ∇ψB)ᵀ, 0]] in (ξ, ν). Where J is singular
// to rounding (two flat faces parallel: superellipsoids of high exponents touching face to face,
// whose Hessians vanish along the faces, so that the point is barely determined along them
// while the level is), the step is J's truncated pseudo-inverse applied to −r: singular values
// below 1e-12 of the largest dropped (an SVD), so that it solves the determined directions (the
// level's, across the faces) as Newton's step would and leaves the flat ones where they are.
Solve4Result NewtonStep(const NewtonPoint3& p, bool& truncated)
{
	const Sym33 H = p.A.hess + p.mu * p.B.hess;
	const Vec3 dmu = p.mu * p.B.grad, row = p.A.grad - p.B.grad;
	const double minusR[4] = {-p.r[0], -p.r[1], -p.r[2], -p.r[3]};
	const double J[4][4] = {{H.xx, H.xy, H.xz, dmu.x}, {H.xy, H.yy, H.yz, dmu.y}, {H.xz, H.yz, H.zz, dmu.z}, {row.x, row.y, row.z, 0.0}};
	Solve4Result step = Solve4(J, minusR);
	truncated = false;
	if (step.rcond > 1e-14)
		return step;
	Eigen::Matrix4d M;
	for (int i = 0; i < 4; ++i)
		for (int k = 0; k < 4; ++k)
			M(i, k) = J[i][k];
	if (!M.allFinite())
		return step;
	const Eigen::JacobiSVD<Eigen::Matrix4d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
	const Eigen::Vector4d sigma = svd.singularValues();
	if (!(sigma(0) > 0.0))
		return step;
	const Eigen::Vector4d ur = svd.matrixU().transpose() * Eigen::Vector4d(minusR[0], minusR[1], minusR[2], minusR[3]);
	Eigen::Vector4d scaled = Eigen::Vector4d::Zero();
	for (int i = 0; i < 4; ++i)
		if (sigma(i) > 1e-12 * sigma(0))
			scaled(i) = ur(i) / sigma(i);
	const Eigen::Vector4d x = svd.matrixV() * scaled;
	for (int i = 0; i < 4; ++i)
		step.x[i] = x(i);
	step.rcond = 1.0; // usable: the dropped directions are not stepped along
	truncated = true;
	return step;
}

// Where Newton's direction does not lower the residual (the Jacobian nearly singular: flat faces
// of high exponents touching face to face), Levenberg–Marquardt's on the weighted residual
// ½ rᵀWr, W = diag(w12, w12, w12, w3) the line search's frozen weights: d = −(JᵀWJ + λI)⁻¹JᵀWr,
// which for growing λ turns towards steepest descent and so lowers the residual for a short
// enough step. λ from 1e-8 of JᵀWJ's mean diagonal up by thousandfolds. True with `trial` set
// where a step is accepted.
bool RecoveryStep(const PairFrame3& f, const NewtonPoint3& p, double w12, double w3, double trust, double merit0,
                  const std::function<double(const NewtonPoint3&)>& merit, NewtonPoint3& trial)
{
	const Sym33 H = p.A.hess + p.mu * p.B.hess;
	const Vec3 dmu = p.mu * p.B.grad, row = p.A.grad - p.B.grad;
	Eigen::Matrix4d J;
	J << H.xx, H.xy, H.xz, dmu.x, H.xy, H.yy, H.yz, dmu.y, H.xz, H.yz, H.zz, dmu.z, row.x, row.y, row.z, 0.0;
	const Eigen::Vector4d w(w12, w12, w12, w3), r(p.r[0], p.r[1], p.r[2], p.r[3]);
	const Eigen::Matrix4d M = J.transpose() * w.asDiagonal() * J;
	const Eigen::Vector4d g = J.transpose() * (w.asDiagonal() * r);
	const double mean = 0.25 * M.trace();
	if (!(mean > 0.0) || !std::isfinite(mean) || !g.allFinite())
		return false;
	for (double lambda = 1e-8; lambda <= 10.0; lambda *= 1e3)
	{
		const Eigen::Vector4d d = -(M + lambda * mean * Eigen::Matrix4d::Identity()).ldlt().solve(g);
		if (!d.allFinite())
			continue;
		double limit = 1.0;
		const double stepXi = std::max({std::fabs(d(0)), std::fabs(d(1)), std::fabs(d(2))});
		if (stepXi > trust)
			limit = trust / stepXi;
		if (std::fabs(d(3)) > 2.0)
			limit = std::min(limit, 2.0 / std::fabs(d(3)));
		double alpha = limit;
		for (int k = 0; k < 20; ++k, alpha *= 0.5)
		{
			Evaluate(f, p.xi + alpha * Vec3(d(0), d(1), d(2)), p.nu + alpha * d(3), trial);
			if (trial.finite && merit(trial) < merit0)
				return true;
		}
	}
	return false;
}
} // namespace

LevelResult3 RunNewton3(const PairFrame3& f, Vec3 xi, double nu, const SolverOptions& options)
{
	LevelResult3 result;
	result.method = SolveMethod::newton;
	const double trust = std::max(0.5, 0.5 * Length(f.Xi(f.b.pose.p) - f.Xi(f.a.pose.p)));
	NewtonPoint3 points[2];
	NewtonPoint3* current = &points[0];
	NewtonPoint3* trial = &points[1];
	Evaluate(f, xi, nu, *current);
	const int cap = std::max(1, options.maxIterations);
	for (int it = 1; it <= cap; ++it)
	{
		NewtonPoint3& p = *current;
		result.iterations = it;
		if (!p.finite)
		{
			result.failure = "non-finite level value or derivative during Newton iteration";
			return result;
		}
		TakeLeastSquaresMultiplier(p);
		// At the rounding floor (computed where a step fails: a comparison on the common path).
		auto atFloor = [&]() { return p.relative < RoundingFloor(f, p); };
		bool shifted = false; // a truncated or recovery step: its length says nothing of convergence
		const Solve4Result step = NewtonStep(p, shifted);
		if (!(step.rcond > 1e-14))
		{
			if (atFloor())
				break; // singular only at the answer's rounding level
			result.failure = "singular or ill-conditioned Jacobian";
			return result;
		}
		double delta[4] = {step.x[0], step.x[1], step.x[2], step.x[3]};
		// Trust region: half the pair's size (or of the centres' distance) in ξ, e² in μ.
		double limit = 1.0;
		const double stepXi = std::max({std::fabs(delta[0]), std::fabs(delta[1]), std::fabs(delta[2])});
		if (stepXi > trust)
			limit = std::min(limit, trust / stepXi);
		if (std::fabs(delta[3]) > 2.0)
			limit = std::min(limit, 2.0 / std::fabs(delta[3]));
		for (double& d : delta)
			d *= limit;
		// Backtracking on the residual with row weights frozen at the current point.
		const double w12 = 1.0 / (LengthSquared(p.A.grad) + p.mu * p.mu * LengthSquared(p.B.grad) + 1e-300);
		const double w3 = 1.0 / (p.A.psi * p.A.psi + p.B.psi * p.B.psi + 1e-300);
		auto merit = [&](const NewtonPoint3& q) {
			return w12 * (q.r[0] * q.r[0] + q.r[1] * q.r[1] + q.r[2] * q.r[2]) + w3 * q.r[3] * q.r[3];
		};
		const double merit0 = merit(p);
		double alpha = 1.0;
		bool accepted = false, floorReached = false;
		for (int k = 0; k < 40; ++k, alpha *= 0.5)
		{
			if (k == 3 && (floorReached = atFloor()))
				break; // at the rounding floor more halvings cannot help
			Evaluate(f, p.xi + alpha * Vec3(delta[0], delta[1], delta[2]), p.nu + alpha * delta[3], *trial);
			if (trial->finite && merit(*trial) <= (1.0 - 1e-4 * alpha) * merit0)
			{
				accepted = true;
				break;
			}
		}
		if (!accepted)
		{
			if (floorReached || atFloor())
				break; // rounding floor: no step lowers the residual any more
			if (!RecoveryStep(f, p, w12, w3, trust, merit0, merit, *trial))
			{
				result.failure = "line search stalled (no step lowers the residual)";
				return result;
			}
			shifted = true; // not a Newton step: no convergence read from its length
			alpha = 0.0;
		}
		const double moved = alpha * std::max({std::fabs(delta[0]), std::fabs(delta[1]), std::fabs(delta[2])});
		std::swap(current, trial);
		const bool full = limit == 1.0 && alpha == 1.0 && !shifted;
		// Converged only where the conditions hold at the new point (its gauges are evaluated, so
		// the test is a comparison); else Newton goes on from it, within the cap. (The rounding-
		// floor exits above have the point's own rounding as their standard: near-tangent plates of
		// aspect 100 stop there with levels 1e-9 apart, which ConditionsHold3's cap of 1e-9/q in the
		// gauges would refuse, sending warm starts to a cold solve.)
		// A relative residual under 1e-12 holds the levels to 2e-12 and the normals to 3e-12 rad,
		// within the test's tolerances: the common case is one comparison.
		if (((full && moved <= options.stepTolerance) || current->relative < 1e-15) &&
		    (current->relative < 1e-12 || ConditionsHold3(f, current->xi, current->A, current->B)))
			break;
		if (it == cap)
		{
			result.failure = "iteration cap reached";
			return result;
		}
	}
	const NewtonPoint3& p = *current;
	// A solution has opposed gradients; deep inside both particles tiny parallel gradients can
	// pass the residual test.
	if (!(Dot(Normalize(p.A.grad), Normalize(p.B.grad)) < -1.0 + 1e-6))
	{
		result.failure = "converged to a point where the gradients are not opposed";
		return result;
	}
	result.status = SolveStatus::converged;
	result.failure = "";
	result.level = p.A.lambda;
	result.point = f.World(p.xi);
	result.normal = Normalize(p.A.grad);
	result.multiplier = p.mu;
	return result;
}

bool ConditionsHold3(const PairFrame3& f, Vec3 xi)
{
	return ConditionsHold3(f, xi, f.Eval(f.a, xi, true), f.Eval(f.b, xi, true));
}

bool ConditionsHold3(const PairFrame3& f, Vec3 xi, const GaugeValue3& A, const GaugeValue3& B)
{
	const double eps = std::numeric_limits<double>::epsilon();
	const double la = Length(A.grad), lb = Length(B.grad), mean = 0.5 * (A.psi + B.psi);
	if (!(A.finite && B.finite && la > 0.0 && lb > 0.0 && mean > 0.0))
		return false;
	const double reach = std::max({Length(f.World(xi)), Length(f.a.pose.p), Length(f.b.pose.p)});
	const double delta = eps * reach / f.scale;
	const double level = std::fabs(A.psi - B.psi) / mean, levelFloor = (la + lb) * delta / mean + 4.0 * eps;
	const double angle = Length(A.grad / la + B.grad / lb);
	const double angleFloor = (RowSumNorm(A.hess) / la + RowSumNorm(B.hess) / lb) * delta + 4.0 * eps;
	return level <= std::max(1e-11, std::min(10.0 * levelFloor, 1e-9 / f.power)) &&
	       angle <= std::max(1e-8, 10.0 * angleFloor);
}

bool GeometricStart3(const PairFrame3& f, Vec3& xi, double& mu)
{
	if (CentresCoincide(*f.a.shape, f.a.pose, *f.b.shape, f.b.pose))
		return false;
	const Vec3 ca = f.Xi(f.a.pose.p), cb = f.Xi(f.b.pose.p);
	// ψA − ψB goes from −ψB(cA) < 0 to ψA(cB) > 0 along the segment: one root. The surfaces'
	// radii along the centre line give it exactly where both ψ are homogeneous of one degree.
	auto phi = [&](double t) {
		const Vec3 x = ca + t * (cb - ca);
		return f.Psi(f.a, x) - f.Psi(f.b, x);
	};
	const Vec3 dir = Normalize(f.b.pose.p - f.a.pose.p);
	const double rA = f.a.shape->RadiusAt(MulT(f.a.R, dir), f.a.shape->SurfaceLevel());
	const double rB = f.b.shape->RadiusAt(MulT(f.b.R, -dir), f.b.shape->SurfaceLevel());
	double t = 0.5;
	if (rA > 0.0 && rB > 0.0 && std::isfinite(rA + rB))
		t = rA / (rA + rB);
	const Vec3 xt = ca + t * (cb - ca);
	const double psiA = f.Psi(f.a, xt), psiB = f.Psi(f.b, xt);
	const double phiT = psiA - psiB;
	if (!(std::fabs(phiT) <= 1e-9 * (psiA + psiB)))
	{
		const ScalarResult r = phiT > 0.0 ? FindRootBrent(phi, 0.0, t, phi(0.0), phiT, 1e-10, 100)
		                                  : FindRootBrent(phi, t, 1.0, phiT, phi(1.0), 1e-10, 100);
		t = r.x;
	}
	xi = ca + t * (cb - ca);
	const double ga = Length(f.Eval(f.a, xi, false).grad), gb = Length(f.Eval(f.b, xi, false).grad);
	mu = (ga > 0.0 && gb > 0.0 && std::isfinite(ga / gb)) ? ga / gb : 1.0;
	return true;
}

bool NewtonApplies3(const Shape3& a, const Shape3& b, LevelResult3& failure)
{
	failure.method = SolveMethod::newton;
	if (a.IsSmoothConvex() && b.IsSmoothConvex())
		return true;
	failure.failure = "Newton needs smooth, strictly convex shapes (superellipsoid exponents >= 2)";
	return false;
}

LevelResult3 SolveCommonLevelNewton(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                    const SolverOptions& options, const WarmStart3* warm)
{
	LevelResult3 result;
	if (!NewtonApplies3(a, b, result))
		return result;
	const PairFrame3 f(a, pa, b, pb);
	Vec3 xi;
	double mu = 1.0;
	if (warm && warm->valid && warm->multiplier > 0.0 && IsFinite(warm->localPoint) && IsFinite(warm->localPointB))
	{
		// Where the point went with each body: their mean.
		xi = f.Xi(0.5 * (ToWorld(pa, warm->localPoint) + ToWorld(pb, warm->localPointB)));
		mu = warm->multiplier;
	}
	else if (!GeometricStart3(f, xi, mu))
	{
		result.failure = "coincident centres: no common-level point between them";
		return result;
	}
	return RunNewton3(f, xi, std::log(mu), options);
}

void RecordWarmStart3(WarmStart3* warm, const Pose3& pa, const Pose3& pb, const LevelResult3& level)
{
	if (!warm)
		return;
	if (!(level.Ok() && level.multiplier > 0.0))
	{
		warm->valid = false;
		return;
	}
	warm->valid = true;
	warm->localPoint = ToBody(pa, level.point);
	warm->localPointB = ToBody(pb, level.point);
	warm->multiplier = level.multiplier;
}

} // namespace b2a
