// b2a_viewer: the paper's collision processes (its Figures 4, 8 and 10) in a Box2D world: two
// particles move and turn with constant velocities (no gravity) and collide. The exact first
// contact from b2a::TimeOfImpact is drawn as grey outlines with its point; the panel says when
// fixed stepping (the world's own steps, the paper's 440 over the interval) first finds them
// overlapping, and how late that is. Until then the particles are kinematic bodies: Box2D turns
// those about their origin, as b2a::Motion does (a dynamic body turns about its centre of mass,
// which for a heart is elsewhere); from then on they are dynamic and collide.
#include "samples/PairSample.h"
#include "samples/Samples.h"

#include "common/PaperCases.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/b2analytic.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace b2a::viewer
{
namespace
{
// The paper steps its superellipses 440 times over their 0.05 s interval.
constexpr int kStepsPerInterval = 440;

class CollisionCases : public PairSample
{
public:
	CollisionCases() : m_cases(demo::PaperCollisionCases())
	{
		LoadCase(0);
	}

	SampleDefaults Defaults() const override
	{
		const demo::CollisionCase& c = m_cases[size_t(m_case)];
		SampleDefaults d = PairDefaults();
		d.step.hertz = kStepsPerInterval / 0.05; // the superellipses' 0.05 s in the paper's 440 steps
		d.step.sleep = false;
		d.bodySize = float(std::max(c.a->BoundingRadius(), c.b->BoundingRadius()));
		d.metre = 100.0f * d.bodySize; // the mouse joint's force in the scene's own scale
		d.mouseHertz = 200.0f;
		d.polygonTwin = false; // the first overlap is found by the analytic contact
		return d;
	}

	void Status(std::vector<std::string>& lines) const override
	{
		Sample::Status(lines);
		char line[256];
		if (m_toi.hit)
			std::snprintf(line, sizeof(line), "exact first contact (grey): t = %.9f s at (%.5f, %.5f)", m_toi.time, m_toi.contact.point.x,
			              m_toi.contact.point.y);
		else
			std::snprintf(line, sizeof(line), "no contact within %.3g s", m_cases[size_t(m_case)].tMax);
		lines.push_back(line);
		if (m_steppingTime >= 0.0)
			std::snprintf(line, sizeof(line), "fixed stepping first finds them overlapping at t = %.6f s: %.3g s late", m_steppingTime,
			              m_steppingTime - m_toi.time);
		else
			std::snprintf(line, sizeof(line), "fixed stepping has not found them overlapping yet");
		lines.push_back(line);
		lines.push_back("N: next case; R replays");
	}

	std::map<std::string, double> Readings() const override
	{
		return {{"case", m_case}, {"toi", m_toi.hit ? m_toi.time : -1.0}, {"stepping_time", m_steppingTime}};
	}

	void Panel() override
	{
		if (!ImGui::CollapsingHeader("Collision case", ImGuiTreeNodeFlags_DefaultOpen))
			return;
		if (ImGui::BeginCombo("case", m_cases[size_t(m_case)].name.c_str()))
		{
			for (size_t i = 0; i < m_cases.size(); ++i)
				if (ImGui::Selectable(m_cases[i].name.c_str(), int(i) == m_case))
					LoadCase(int(i));
			ImGui::EndCombo();
		}
	}

	bool Keyboard(int key) override
	{
		if (key == GLFW_KEY_N)
		{
			LoadCase((m_case + 1) % int(m_cases.size()));
			return true;
		}
		return Sample::Keyboard(key);
	}

	void Draw(DrawBatch& batch, const DrawSettings& draw) override
	{
		const demo::CollisionCase& c = m_cases[size_t(m_case)];
		const double t = m_toi.hit ? m_toi.time : c.tMax;
		for (const auto& [shape, motion] : {std::pair(c.a, c.ma), std::pair(c.b, c.mb)})
		{
			const std::vector<b2Vec2> ghost = LevelOutline(*shape, motion.At(t));
			batch.DrawPolygon(ghost.data(), int32(ghost.size()), b2Color(0.6f, 0.6f, 0.6f));
			const Vec2 p0 = motion.pose.p, p1 = motion.At(t).p;
			batch.DrawSegment(b2Vec2(float(p0.x), float(p0.y)), b2Vec2(float(p1.x), float(p1.y)), b2Color(0.5f, 0.5f, 0.5f));
		}
		if (m_toi.hit)
			batch.DrawPoint(b2Vec2(float(m_toi.contact.point.x), float(m_toi.contact.point.y)), 9.0f, b2Color(1.0f, 0.2f, 0.2f));
		Sample::Draw(batch, draw);
	}

protected:
	void AfterStep() override
	{
		if (m_steppingTime >= 0.0)
			return;
		const ContactResult r = ComputeFixtureContact(m_bodies[0]->GetFixtureList(), m_bodies[1]->GetFixtureList());
		if (!r.Ok() || !r.touching)
			return;
		m_steppingTime = Time();
		// The same motion goes on in dynamic bodies: b2Body::ResetMassData gives the centre of
		// mass the origin's velocity plus the turn's, ω × (c − p).
		for (b2Body* b : m_bodies)
			b->SetType(b2_dynamicBody);
	}

private:
	void LoadCase(int index)
	{
		m_case = index;
		const demo::CollisionCase& c = m_cases[size_t(index)];
		const ShapePtr shapes[2] = {c.a, c.b};
		const Pose poses[2] = {c.ma.pose, c.mb.pose};
		ReplacePair(shapes, poses, 0.3f, 0.5f);
		const Motion* motions[2] = {&c.ma, &c.mb};
		for (int i = 0; i < 2; ++i)
		{
			m_bodies[i]->SetType(b2_kinematicBody);
			m_bodies[i]->SetLinearVelocity(b2Vec2(float(motions[i]->velocity.x), float(motions[i]->velocity.y)));
			m_bodies[i]->SetAngularVelocity(float(motions[i]->angularVelocity));
		}
		m_toi = TimeOfImpact(*c.a, c.ma, *c.b, c.mb, c.tMax);
		m_steppingTime = -1.0;
		// The view holds the paths from the start to twice the contact time.
		std::vector<std::vector<b2Vec2>> outlines;
		const double tEnd = std::min(c.tMax, 2.0 * (m_toi.hit ? m_toi.time : c.tMax));
		for (double t : {0.0, 0.5 * tEnd, tEnd})
		{
			outlines.push_back(LevelOutline(*c.a, c.ma.At(t)));
			outlines.push_back(LevelOutline(*c.b, c.mb.At(t)));
		}
		FitView(outlines);
	}

	std::vector<demo::CollisionCase> m_cases;
	int m_case = 0;
	TimeOfImpactResult m_toi;
	double m_steppingTime = -1.0;
};
} // namespace

std::unique_ptr<Sample> MakeCollisionCasesSample()
{
	return std::make_unique<CollisionCases>();
}

} // namespace b2a::viewer
