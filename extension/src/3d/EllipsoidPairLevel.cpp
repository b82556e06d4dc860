// b2analytic: the common level of two ellipsoids by Perram and Wertheim's one-dimensional form,
// and of two spheres in closed form.
#include "3d/Solvers3.h"

#include "b2analytic/3d/SuperellipsoidShape.h"
#include "numerics/RootFinding.h"

#include <Eigen/Dense>

#include <cmath>
#include <typeinfo>

namespace b2a
{

namespace
{
// The shape as an ellipsoid or sphere (n1 = n2 = n3 = 2), else null. The class is final, so
// comparing the dynamic type is exact.
const SuperellipsoidShape* AsEllipsoid(const Shape3& s)
{
	if (typeid(s) != typeid(SuperellipsoidShape))
		return nullptr;
	const auto* e = static_cast<const SuperellipsoidShape*>(&s);
	return (e->Exponent(0) == 2.0 && e->Exponent(1) == 2.0 && e->Exponent(2) == 2.0) ? e : nullptr;
}

// A⁻¹ = R diag(aᵢ²) Rᵀ in units of `scale`: the inverse of the quadratic form of f = xᵀAx.
Eigen::Matrix3d InverseForm(const SuperellipsoidShape& s, const Pose3& p, double scale)
{
	const Mat33 R = ToMatrix(p.q);
	Eigen::Matrix3d M;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
		{
			double v = 0.0;
			for (int k = 0; k < 3; ++k)
				v += R.m[i][k] * (s.Axis(k) / scale) * (s.Axis(k) / scale) * R.m[j][k];
			M(i, j) = v;
		}
	return M;
}
} // namespace

LevelResult3 SphereLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb)
{
	LevelResult3 r;
	r.method = SolveMethod::closedForm;
	const double ra = a.BoundingRadius(), rb = b.BoundingRadius();
	const Vec3 d = pb.p - pa.p;
	const double dist = Length(d);
	if (!(dist > 0.0))
	{
		r.failure = "coincident centres: no common-level point between them";
		return r;
	}
	// Both levels are (distance/radius)²: equal at distance ra/(ra + rb) of the way to B.
	const Vec3 n = d / dist;
	const double s = dist / (ra + rb);
	r.status = SolveStatus::converged;
	r.level = s * s;
	r.point = pa.p + (ra * s) * n;
	r.normal = n;
	// |∇λA| = 2s/ra and |∇λB| = 2s/rb there, opposed.
	r.multiplier = rb / ra;
	return r;
}

LevelResult3 SolveEllipsoidPairLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb)
{
	LevelResult3 result;
	result.method = SolveMethod::ellipsePair;
	const SuperellipsoidShape* ea = AsEllipsoid(a);
	const SuperellipsoidShape* eb = AsEllipsoid(b);
	if (!ea || !eb)
	{
		result.failure = "Perram-Wertheim's form needs two ellipsoids";
		return result;
	}
	if (CentresCoincide(a, pa, b, pb))
	{
		result.failure = "coincident centres: no common-level point between them";
		return result;
	}
	// In units of the pair's size s: with the forms A, B of f = (X − c)ᵀ A (X − c) and r = cB − cA,
	//   F(λ) = λ(1 − λ) rᵀ G(λ)⁻¹ r,  G(λ) = λA⁻¹ + (1 − λ)B⁻¹,
	// is min over X of (1 − λ)fA + λfB, concave in λ, and its maximum over [0, 1] is the common
	// level (min–max duality). With z = G⁻¹r and G' = A⁻¹ − B⁻¹:
	//   F'  = (1 − 2λ) rᵀz − λ(1 − λ) zᵀG'z,
	//   F'' = −2rᵀz − 2(1 − 2λ) zᵀG'z + 2λ(1 − λ) (G'z)ᵀ G⁻¹ (G'z),
	// F'(0) = rᵀBr > 0 and F'(1) = −rᵀAr < 0: the root of F' is bracketed by [0, 1].
	const double s = 0.5 * (a.BoundingRadius() + b.BoundingRadius());
	const Eigen::Matrix3d Ainv = InverseForm(*ea, pa, s), Binv = InverseForm(*eb, pb, s);
	const Eigen::Matrix3d Gd = Ainv - Binv;
	const Vec3 rv = (pb.p - pa.p) / s;
	const Eigen::Vector3d r(rv.x, rv.y, rv.z);
	int evaluations = 0;
	auto solveAt = [&](double lambda, Eigen::Vector3d& z, Eigen::LLT<Eigen::Matrix3d>& llt) {
		llt.compute(lambda * Ainv + (1.0 - lambda) * Binv);
		z = llt.solve(r);
	};
	auto fdf = [&](double lambda, double& d2) {
		++evaluations;
		Eigen::LLT<Eigen::Matrix3d> llt;
		Eigen::Vector3d z;
		solveAt(lambda, z, llt);
		const Eigen::Vector3d w = Gd * z;
		const double rz = r.dot(z), zw = z.dot(w), wv = w.dot(llt.solve(w));
		const double l1 = lambda * (1.0 - lambda);
		d2 = -2.0 * rz - 2.0 * (1.0 - 2.0 * lambda) * zw + 2.0 * l1 * wv;
		return (1.0 - 2.0 * lambda) * rz - l1 * zw;
	};
	double unused;
	const double f0 = fdf(0.0, unused), f1 = fdf(1.0, unused);
	const ScalarResult root = FindRootNewtonSafe(fdf, 0.0, 1.0, f0, f1, 0.0, 100);
	if (!root.converged || !(root.x > 0.0 && root.x < 1.0))
	{
		result.failure = "Perram-Wertheim: the multiplier did not converge";
		result.iterations = evaluations;
		return result;
	}
	const double lambda = root.x;
	Eigen::LLT<Eigen::Matrix3d> llt;
	Eigen::Vector3d z;
	solveAt(lambda, z, llt);
	// The point: (1 − λ)A(X − cA) + λB(X − cB) = 0 gives X = cA + λA⁻¹z; ∇fA = 2λz there and
	// ∇fB = −2(1 − λ)z, so μ = λ/(1 − λ).
	const Eigen::Vector3d p = lambda * (Ainv * z);
	const Vec3 normal = Normalize(Vec3(z(0), z(1), z(2)));
	result.status = SolveStatus::converged;
	result.failure = "";
	result.iterations = evaluations;
	result.level = lambda * (1.0 - lambda) * r.dot(z);
	result.point = pa.p + s * Vec3(p(0), p(1), p(2));
	result.normal = normal;
	result.multiplier = lambda / (1.0 - lambda);
	// F and the point carry the rounding of G's solve, up to its condition number times eps (1e-12
	// at aspect 100). A Newton polish on the common level's own equations from here, inside its
	// quadratic regime, takes one or two steps to rounding.
	const PairFrame3 frame(a, pa, b, pb);
	SolverOptions polish;
	polish.maxIterations = 8;
	const LevelResult3 polished = RunNewton3(frame, frame.Xi(result.point), std::log(result.multiplier), polish);
	if (polished.Ok() && Distance(polished.point, result.point) <= 1e-6 * s)
	{
		result.level = polished.level;
		result.point = polished.point;
		result.normal = polished.normal;
		result.multiplier = polished.multiplier;
		result.iterations += polished.iterations;
	}
	return result;
}

} // namespace b2a
