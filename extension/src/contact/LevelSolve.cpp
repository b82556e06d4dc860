// b2analytic: choosing a level solver, and the names of statuses and methods.
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

LevelResult SolveCommonLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                             const SolverOptions& options, WarmStart* warm)
{
	if (!PoseFinite(pa) || !PoseFinite(pb))
	{
		if (warm)
			warm->valid = false;
		return NonFinitePoseFailure<LevelResult>();
	}
	// The common level needs convex shapes: SolveCommonLevelGrid's refusal for both methods that
	// would take it, before anything is solved or recorded (`warm` stays as it was).
	if (method != MethodChoice::newton && !(a.IsConvex() && b.IsConvex()))
		return SolveCommonLevelGrid(a, pa, b, pb, options);
	LevelResult r;
	LevelSlide slide; // Newton's, for the next warm start
	LevelSlide* keep = warm ? &slide : nullptr;
	const bool smooth = a.IsSmoothConvex() && b.IsSmoothConvex();
	switch (method)
	{
	case MethodChoice::newton:
		r = SolveCommonLevelNewton(a, pa, b, pb, options, warm, keep);
		break;
	case MethodChoice::grid:
		r = SolveCommonLevelGrid(a, pa, b, pb, options);
		break;
	default:
		const SuperellipseShape* ea = AsPlainEllipse(a);
		const SuperellipseShape* eb = ea ? AsPlainEllipse(b) : nullptr;
		if (a.Family() == ShapeFamily::circle && b.Family() == ShapeFamily::circle)
		{
			r = CircleLevel(a, pa, b, pb);
		}
		else if (ea && eb && (r = SolveEllipsePairLevel(*ea, pa, *eb, pb, warm)).Ok())
		{
			// two ellipses: solved without the generic solvers
		}
		else if (smooth)
		{
			r = SolveCommonLevelNewton(a, pa, b, pb, options, warm, keep);
			if (!r.Ok() && warm && warm->valid)
				r = SolveCommonLevelNewton(a, pa, b, pb, options, nullptr, keep);
			if (!r.Ok())
			{
				const int spent = r.iterations;
				r = SolveCommonLevelMinMax(a, pa, b, pb, options);
				r.iterations += spent;
				if (r.Ok())
					r.status = SolveStatus::convergedAfterFallback;
			}
		}
		else
		{
			r = SolveCommonLevelGrid(a, pa, b, pb, options); // convex, not smooth
		}
	}
	CheckResult(r);
	RecordWarmStart(warm, pa, pb, r, &slide); // (valid only where Newton's answer is r)
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
