// b2analytic demos: the paper's Figure 17 scene.
#include "Figure17Scene.h"

#include <algorithm>
#include <cmath>

namespace b2a::demo
{

Figure17Scene MakeFigure17Scene()
{
	Figure17Scene s;
	s.a = MakeSuperellipsoid(4, 4, 4, 6, 6, 12);
	s.b = MakeSuperellipsoid(2, 3, 2, 8, 8, 8);
	s.ma = Motion3{Pose3(Vec3(-10, -15, -10), EulerZXZ(kPi / 9, kPi / 8, kPi / 7)), Vec3(-20, -10, -15), Vec3(20, -30, 2)};
	s.mb = Motion3{Pose3(Vec3(-20, -25, -20), EulerZXZ(kPi / 6, kPi / 5, kPi / 4)), Vec3(10, 20, 15), Vec3(-10, 20, -2)};
	return s;
}

Box3 Figure17SceneBox(const Figure17Scene& s, double tEnd, double tick)
{
	Box3 box{Vec3(1e300, 1e300, 1e300), Vec3(-1e300, -1e300, -1e300)};
	for (int k = 0; k <= 40; ++k)
	{
		const double t = tEnd * k / 40;
		for (const Box3& b : {s.a->ComputeAABB(s.ma.At(t)), s.b->ComputeAABB(s.mb.At(t))})
			for (int i = 0; i < 3; ++i)
			{
				box.lower[i] = std::min(box.lower[i], b.lower[i]);
				box.upper[i] = std::max(box.upper[i], b.upper[i]);
			}
	}
	for (int i = 0; i < 3; ++i)
	{
		box.lower[i] = tick * std::floor(box.lower[i] / tick);
		box.upper[i] = tick * std::ceil(box.upper[i] / tick);
	}
	return box;
}

} // namespace b2a::demo
