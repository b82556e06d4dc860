// b2analytic: a solve's slide into the warm start (internal; the model is in WarmSlide.h).
#include "contact/SolverCore.h"

#include <cmath>

namespace b2a
{

void RecordSlide(WarmStart* warm, const Pose& pa, const Pose& pb, const LevelSlide& slide)
{
	WriteSlide(*warm, InvRotate(pa.q, slide.normal), InvRotate(pb.q, slide.normal), slide.coefficients);
}

} // namespace b2a
