// b2analytic: the names of statuses and methods, the circles' closed form, the one-sided scale.
#include "b2analytic/CommonLevel.h"

#include "contact/ResultChecks.h"
#include "contact/SolverCore.h"
#include "b2analytic/SuperellipseShape.h"

#include <cmath>

namespace b2a
{

const char* StatusName(SolveStatus status)
{
	switch (status)
	{
	case SolveStatus::converged: return "converged";
	case SolveStatus::convergedAfterFallback: return "converged_after_fallback";
	default: return "failed";
	}
}

const char* MethodName(SolveMethod method)
{
	switch (method)
	{
	case SolveMethod::closedForm: return "closed_form";
	case SolveMethod::newton: return "newton";
	case SolveMethod::minMax: return "min_max";
	case SolveMethod::grid: return "grid";
	case SolveMethod::overlapAxis: return "overlap_axis";
	case SolveMethod::separatingAxis: return "separating_axis";
	case SolveMethod::ellipsePair: return "ellipse_pair";
	default: return "none";
	}
}

// Two circles: the common level point divides the centre segment in the ratio of the radii,
// X = cA + rA/(rA + rB)·(cB − cA), and C = (d / (rA + rB))².
LevelResult CircleLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb)
{
	LevelResult r;
	r.method = SolveMethod::closedForm;
	const double ra = a.BoundingRadius(), rb = b.BoundingRadius();
	const Vec2 d = pb.p - pa.p;
	const double dist = Length(d);
	if (!(dist > 0.0))
	{
		r.failure = "coincident centres: no common-level point between them";
		return r;
	}
	r.status = SolveStatus::converged;
	r.point = pa.p + (ra / (ra + rb)) * d;
	r.normal = d / dist;
	const double s = dist / (ra + rb);
	r.level = s * s;
	r.multiplier = rb / ra; // |∇F_A| = 2s/rA, |∇F_B| = 2s/rB at the point, and ∇F_A + μ∇F_B = 0
	return r;
}

LevelResult SolveScaleA(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                        const SolverOptions& options)
{
	if (!PoseFinite(pa) || !PoseFinite(pb))
		return NonFinitePoseFailure<LevelResult>();
	if (method == MethodChoice::newton)
		return CheckedResult(SolveScaleANewton(a, pa, b, pb, options));
	return CheckedResult(SolveGridScale(a, pa, b, pb, options));
}

} // namespace b2a
