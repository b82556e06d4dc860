// b2analytic: a solve's slide into the warm start (internal; the model is in WarmSlide.h).
#include "contact/SolverCore.h"

#include <cmath>

namespace b2a
{

void RecordSlide(WarmStart* warm, const Pose& pa, const Pose& pb, const LevelSlide& slide)
{
	const Vec2 nA = InvRotate(pa.q, slide.normal), nB = InvRotate(pb.q, slide.normal);
	warm->normalA[0] = float(nA.x);
	warm->normalA[1] = float(nA.y);
	warm->normalB[0] = float(nB.x);
	warm->normalB[1] = float(nB.y);
	for (int i = 0; i < 3; ++i)
		warm->slide[i] = float(slide.coefficients[i]);
	warm->hasSlide = std::isfinite(warm->slide[0] + warm->slide[1] + warm->slide[2]);
}

} // namespace b2a
