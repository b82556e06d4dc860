// b2a_viewer: the pair samples' base and drawing helpers.
#include "samples/PairSample.h"

#include "b2analytic/AnalyticFixture.h"

#include <algorithm>
#include <cmath>

namespace b2a::viewer
{

std::vector<b2Vec2> LevelOutline(const Shape& shape, const Pose& pose, double level, int count)
{
	if (!(level > 0.0))
		level = shape.SurfaceLevel();
	std::vector<b2Vec2> out;
	out.reserve(size_t(count));
	for (int k = 0; k < count; ++k)
	{
		const Vec2 p = ToWorld(pose, shape.SurfacePoint(-kPi + 2.0 * kPi * k / count, level));
		out.push_back(b2Vec2(float(p.x), float(p.y)));
	}
	return out;
}

void GrowBox(const std::vector<b2Vec2>& points, b2Vec2& lo, b2Vec2& hi)
{
	for (b2Vec2 p : points)
	{
		lo = b2Vec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
		hi = b2Vec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
	}
}

void DrawArrow(DrawBatch& batch, b2Vec2 from, b2Vec2 to, const b2Color& color)
{
	batch.DrawSegment(from, to, color);
	const b2Vec2 d = to - from;
	const float length = d.Length();
	if (length <= 0.0f)
		return;
	const b2Vec2 u = (1.0f / length) * d, n(-u.y, u.x);
	const float h = 0.25f * length;
	batch.DrawSegment(to, to - h * u + 0.5f * h * n, color);
	batch.DrawSegment(to, to - h * u - 0.5f * h * n, color);
}

PairSample::PairSample()
{
	MakeWorld(b2Vec2(0.0f, 0.0f));
}

void PairSample::ReplacePair(const ShapePtr shapes[2], const Pose poses[2], float friction, float restitution)
{
	ResetClock();
	for (int i = 0; i < 2; ++i)
	{
		if (m_bodies[i])
			World()->DestroyBody(m_bodies[i]);
		const Pose& p = poses[i];
		m_bodies[i] = AddParticle(shapes[i], b2Vec2(float(p.p.x), float(p.p.y)), float(p.q.Angle()), 1.0f, friction, restitution);
	}
}

void PairSample::FitView(const std::vector<std::vector<b2Vec2>>& outlines)
{
	m_viewLo = b2Vec2(1e30f, 1e30f);
	m_viewHi = -m_viewLo;
	for (const auto& o : outlines)
		GrowBox(o, m_viewLo, m_viewHi);
	RequestView();
}

SampleDefaults PairSample::PairDefaults() const
{
	SampleDefaults d = MetreScene(m_viewLo, m_viewHi, 10.0f);
	const b2Vec2 size = m_viewHi - m_viewLo;
	d.bodySize = 0.1f * std::max(size.x, size.y);
	return d;
}

Pose PairSample::PoseOf(int i) const
{
	return GetAnalyticPose(m_bodies[i]->GetFixtureList());
}

} // namespace b2a::viewer
