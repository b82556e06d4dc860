// b2analytic validation: the area fraction of a packing inside a window, and its free surface.
#include "validation/PackingWindow.h"

#include <algorithm>
#include <cmath>

namespace b2a::demo
{

WindowFraction MeasureWindow(const std::vector<ParticleState>& packing, Box window, double h)
{
	WindowFraction out;
	const double nxReal = (window.upper.x - window.lower.x) / h, nyReal = (window.upper.y - window.lower.y) / h;
	if (!(h > 0.0) || !(nxReal >= 1.0) || !(nyReal >= 1.0) || nxReal * nyReal > 1e9)
		return out;
	const int nx = int(nxReal), ny = int(nyReal);
	std::vector<unsigned char> covered(size_t(nx) * size_t(ny), 0);
	long long inside = 0;
	for (const ParticleState& p : packing)
	{
		// The cells whose centres lie in the particle's bounding box.
		const Box box = p.shape->ComputeAABB(p.pose);
		const int i0 = std::max(0, int(std::ceil((box.lower.x - window.lower.x) / h - 0.5)));
		const int i1 = std::min(nx - 1, int(std::floor((box.upper.x - window.lower.x) / h - 0.5)));
		const int j0 = std::max(0, int(std::ceil((box.lower.y - window.lower.y) / h - 0.5)));
		const int j1 = std::min(ny - 1, int(std::floor((box.upper.y - window.lower.y) / h - 0.5)));
		const double level = p.shape->SurfaceLevel();
		for (int j = j0; j <= j1; ++j)
			for (int i = i0; i <= i1; ++i)
			{
				const Vec2 x(window.lower.x + (i + 0.5) * h, window.lower.y + (j + 0.5) * h);
				if (p.shape->Level(InvRotate(p.pose.q, x - p.pose.p)) <= level)
				{
					++inside;
					covered[size_t(j) * size_t(nx) + size_t(i)] = 1;
				}
			}
	}
	long long union_ = 0;
	for (unsigned char c : covered)
		union_ += c;
	const double cells = double(nx) * double(ny);
	out.sum = double(inside) / cells;
	out.covered = double(union_) / cells;
	out.width = nx * h;
	out.height = ny * h;
	return out;
}

double FreeSurface(const std::vector<ParticleState>& packing, double boxWidth, double column)
{
	const int columns = std::max(1, int(boxWidth / column));
	std::vector<double> top(size_t(columns), 0.0);
	for (const ParticleState& p : packing)
	{
		const int k = std::clamp(int((p.pose.p.x + 0.5 * boxWidth) / boxWidth * columns), 0, columns - 1);
		top[size_t(k)] = std::max(top[size_t(k)], p.shape->ComputeAABB(p.pose).upper.y);
	}
	return *std::min_element(top.begin(), top.end());
}

} // namespace b2a::demo
