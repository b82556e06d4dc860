// b2analytic: the 3D shape base: cached surface samples, AABB from the support function.
#include "b2analytic/3d/Shape3.h"

#include <algorithm>

namespace b2a
{

int SurfaceSamples3::Neighbours(int i, std::vector<int>& out) const
{
	out.clear();
	if (i == SouthPole() || i == NorthPole())
	{
		const int r = i == SouthPole() ? 0 : rings - 1;
		for (int k = 0; k < perRing; ++k)
			out.push_back(Index(r, k));
		return int(out.size());
	}
	const int r = i / perRing, k = i % perRing;
	for (int dr = -1; dr <= 1; ++dr)
	{
		const int rr = r + dr;
		if (rr < 0 || rr >= rings)
		{
			out.push_back(rr < 0 ? SouthPole() : NorthPole());
			continue;
		}
		for (int dk = -1; dk <= 1; ++dk)
			if (dr != 0 || dk != 0)
				out.push_back(Index(rr, k + dk));
	}
	return int(out.size());
}

Shape3::Shape3(ShapeKind kind, double surfaceLevel, bool convex, bool smoothConvex, double levelPower)
	: m_kind(kind), m_surfaceLevel(surfaceLevel), m_convex(convex), m_smoothConvex(smoothConvex), m_levelPower(levelPower)
{
	if (KindDimension(kind) != 3)
		throw InvalidParameter(std::string("3D shape: field 'kind' must be a registered kind of dimension 3, got \"") +
		                           b2a::KindName(kind) + "\"",
		                       "kind");
}

Shape3::~Shape3() = default;

void Shape3::Finalize(double boundingRadius, const MassProperties3& mass)
{
	m_boundingRadius = boundingRadius;
	m_mass = mass;
}

Vec3 Shape3::PointOnRay(Vec3 x, double level) const
{
	const Vec3 u = Normalize(x);
	return RadiusAt(u, level) * u;
}

Box3 Shape3::ComputeAABB(const Pose3& pose) const
{
	// Along world axis e the particle reaches p·e + h(Rᵀe) and p·e − h(−Rᵀe); the shapes are
	// symmetric about their centre, so h(−u) = h(u). The rows of R are the world axes in the body.
	const Mat33 R = ToMatrix(pose.q);
	Box3 box;
	for (int k = 0; k < 3; ++k)
	{
		const double h = SupportValue(R.Row(k));
		box.lower[k] = pose.p[k] - h;
		box.upper[k] = pose.p[k] + h;
	}
	return box;
}

const SurfaceSamples3& Shape3::Samples(int count) const
{
	count = std::max(count, 16);
	// Lock-free where the count is the last one asked for (the grid method asks with one count).
	const SurfaceSamples3* last = m_lastSamples.load(std::memory_order_acquire);
	if (last && last->requested == count)
		return *last;
	std::lock_guard<std::mutex> lock(m_sampleMutex);
	for (const auto& entry : m_samples)
		if (entry.first == count)
		{
			m_lastSamples.store(entry.second.get(), std::memory_order_release);
			return *entry.second;
		}
	auto built = std::make_unique<SurfaceSamples3>(BuildSamples(count));
	built->requested = count;
	const SurfaceSamples3* result = built.get();
	m_samples.emplace_back(count, std::move(built));
	m_lastSamples.store(result, std::memory_order_release);
	return *result;
}

} // namespace b2a
