// b2a_viewer: the pair inspector on the paper's contact cases (its Figures 2, 3, 6, 7, 9 and 16,
// live): two particles the user drags (left button) and turns (Q and E, or the sliders), their
// common level with both outlines rescaled to it (or A rescaled onto B's surface, as each case
// says), the contact point, normal and separation, the method, its iterations and solve time,
// all recomputed every frame.
#include "samples/PairSample.h"
#include "samples/Samples.h"

#include "common/PaperCases.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/b2analytic.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace b2a::viewer
{
namespace
{
class ContactCases : public PairSample
{
public:
	ContactCases() : m_cases(demo::PaperContactCases())
	{
		LoadCase(0);
	}

	SampleDefaults Defaults() const override
	{
		SampleDefaults d = PairDefaults();
		d.polygonTwin = false; // the inspector is about the analytic solvers themselves
		return d;
	}

	void Status(std::vector<std::string>& lines) const override
	{
		const demo::ContactCase& c = m_cases[size_t(m_case)];
		char line[256];
		lines.push_back(c.name + ": " + c.description);
		std::snprintf(line, sizeof(line), "%s level %.10g at (%.6g, %.6g), normal (%.4f, %.4f)",
		              c.mode == "common" ? "common" : "A's", m_level.level, m_level.point.x, m_level.point.y, m_level.normal.x,
		              m_level.normal.y);
		lines.push_back(line);
		std::snprintf(line, sizeof(line), "method %s, %s%s%s, %d iterations, %.2f us a solve", MethodName(m_level.method),
		              StatusName(m_level.status), m_level.Ok() ? "" : ": ", m_level.failure, m_level.iterations, m_micros);
		lines.push_back(line);
		std::snprintf(line, sizeof(line), "contact: separation %.6g (%s), by %s, %d iterations", m_contact.separation,
		              m_contact.touching ? "touching" : "apart", MethodName(m_contact.method), m_contact.iterations);
		lines.push_back(line);
		if (c.paperLevel > 0.0)
		{
			std::snprintf(line, sizeof(line), "the paper: level %.6g at (%.4f, %.4f) (green) for its poses", c.paperLevel,
			              c.paperPoint.x, c.paperPoint.y);
			lines.push_back(line);
		}
		lines.push_back("drag a particle with the left button; Q and E turn the last one dragged; N next case");
	}

	void Panel() override
	{
		if (!ImGui::CollapsingHeader("Pair inspector", ImGuiTreeNodeFlags_DefaultOpen))
			return;
		const demo::ContactCase& c = m_cases[size_t(m_case)];
		if (ImGui::BeginCombo("case", c.name.c_str()))
		{
			for (size_t i = 0; i < m_cases.size(); ++i)
				if (ImGui::Selectable(m_cases[i].name.c_str(), int(i) == m_case))
					LoadCase(int(i));
			ImGui::EndCombo();
		}
		const char* methods[] = {"automatic", "newton", "grid"};
		int method = int(m_method);
		if (ImGui::Combo("method", &method, methods, 3))
			m_method = MethodChoice(method);
		for (int i = 0; i < 2; ++i)
		{
			b2Body* b = m_bodies[i];
			float angle = b->GetAngle();
			b2Vec2 p = b->GetPosition();
			ImGui::PushID(i);
			bool changed = ImGui::DragFloat2(i == 0 ? "A position" : "B position", &p.x, 0.01f * Defaults().bodySize);
			changed |= ImGui::SliderAngle(i == 0 ? "A angle" : "B angle", &angle, -180.0f, 180.0f);
			ImGui::PopID();
			if (changed)
				b->SetTransform(p, angle);
		}
	}

	bool Keyboard(int key) override
	{
		if (key == GLFW_KEY_Q || key == GLFW_KEY_E)
		{
			b2Body* b = m_bodies[m_last];
			b->SetTransform(b->GetPosition(), b->GetAngle() + (key == GLFW_KEY_Q ? 1.0f : -1.0f) * b2_pi / 36.0f);
			return true;
		}
		if (key == GLFW_KEY_N)
		{
			LoadCase((m_case + 1) % int(m_cases.size()));
			return true;
		}
		return false; // no bombs here
	}

	bool MouseDown(b2Vec2 p) override
	{
		for (int i = 0; i < 2; ++i)
			if (m_bodies[i]->GetFixtureList()->TestPoint(p))
			{
				m_drag = i;
				m_last = i;
				m_grab = p - m_bodies[i]->GetPosition();
				return true;
			}
		return false;
	}

	void MouseMove(b2Vec2 p) override
	{
		if (m_drag >= 0)
			m_bodies[m_drag]->SetTransform(p - m_grab, m_bodies[m_drag]->GetAngle());
	}

	void MouseUp(b2Vec2 p) override
	{
		(void)p;
		m_drag = -1;
	}

	void Draw(DrawBatch& batch, const DrawSettings& draw) override
	{
		Inspect();
		Sample::Draw(batch, draw);
		const demo::ContactCase& c = m_cases[size_t(m_case)];
		const Pose pa = PoseOf(0), pb = PoseOf(1);
		if (m_level.Ok())
		{
			// The outlines rescaled: both to the common level, or A to its level on B's surface.
			const bool common = c.mode == "common";
			const double levelA = m_level.level * (common ? c.a->SurfaceLevel() : 1.0);
			const double levelB = common ? m_level.level * c.b->SurfaceLevel() : c.b->SurfaceLevel();
			const std::vector<b2Vec2> oa = LevelOutline(*c.a, pa, levelA, 192), ob = LevelOutline(*c.b, pb, levelB, 192);
			batch.DrawPolygon(oa.data(), int32(oa.size()), b2Color(0.45f, 0.65f, 1.0f));
			batch.DrawPolygon(ob.data(), int32(ob.size()), b2Color(1.0f, 0.65f, 0.3f));
			const b2Vec2 point(float(m_level.point.x), float(m_level.point.y));
			const b2Vec2 normal(float(m_level.normal.x), float(m_level.normal.y));
			DrawArrow(batch, point, point + 1.5f * Defaults().bodySize * normal, b2Color(1.0f, 0.3f, 0.3f));
			batch.DrawPoint(point, 9.0f, b2Color(1.0f, 0.2f, 0.2f));
		}
		if (m_contact.Ok())
		{
			// The contact the Box2D adapter uses: the two surface points and the gap between them.
			const b2Vec2 a(float(m_contact.pointA.x), float(m_contact.pointA.y)), b(float(m_contact.pointB.x), float(m_contact.pointB.y));
			batch.DrawSegment(a, b, b2Color(1.0f, 1.0f, 0.3f));
			batch.DrawPoint(a, 6.0f, b2Color(0.45f, 0.65f, 1.0f));
			batch.DrawPoint(b, 6.0f, b2Color(1.0f, 0.65f, 0.3f));
		}
		if (c.paperLevel > 0.0)
			batch.DrawPoint(b2Vec2(float(c.paperPoint.x), float(c.paperPoint.y)), 7.0f, b2Color(0.2f, 0.85f, 0.3f));
	}

	std::map<std::string, double> Readings() const override
	{
		return {{"case", m_case},
		        {"level", m_level.level},
		        {"point_x", m_level.point.x},
		        {"point_y", m_level.point.y},
		        {"iterations", m_level.iterations},
		        {"solved", m_level.Ok() ? 1.0 : 0.0},
		        {"solve_us", m_micros},
		        {"separation", m_contact.separation}};
	}

protected:
	void StepWorld(float, int, int) override {} // the pair is posed by hand, not simulated

private:
	void LoadCase(int index)
	{
		m_case = index;
		const demo::ContactCase& c = m_cases[size_t(index)];
		const Pose poses[2] = {c.pa, c.pb};
		const ShapePtr shapes[2] = {c.a, c.b};
		ReplacePair(shapes, poses);
		m_method = c.method;
		Inspect();
		// The view holds both particles and their rescaled outlines.
		std::vector<std::vector<b2Vec2>> outlines = {LevelOutline(*c.a, c.pa), LevelOutline(*c.b, c.pb)};
		if (m_level.Ok())
		{
			const bool common = c.mode == "common";
			outlines.push_back(LevelOutline(*c.a, c.pa, m_level.level * (common ? c.a->SurfaceLevel() : 1.0)));
			if (common)
				outlines.push_back(LevelOutline(*c.b, c.pb, m_level.level * c.b->SurfaceLevel()));
		}
		FitView(outlines);
	}

	// Solve the pair at its current poses: the level (timed over repeats of at least a
	// millisecond in all, so that one frame's figure means something) and the adapter's contact.
	void Inspect()
	{
		const demo::ContactCase& c = m_cases[size_t(m_case)];
		demo::ContactCase posed = c;
		posed.pa = PoseOf(0);
		posed.pb = PoseOf(1);
		posed.method = m_method;
		using Clock = std::chrono::steady_clock;
		const auto t0 = Clock::now();
		int repeats = 0;
		do
		{
			m_level = posed.Solve();
			++repeats;
		} while (repeats < 1000 && std::chrono::duration<double, std::milli>(Clock::now() - t0).count() < 1.0);
		m_micros = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / repeats;
		m_contact = ComputeContact(*c.a, posed.pa, *c.b, posed.pb, m_method);
	}

	std::vector<demo::ContactCase> m_cases;
	int m_case = 0;
	MethodChoice m_method = MethodChoice::automatic;
	LevelResult m_level;
	ContactResult m_contact;
	double m_micros = 0.0;
	int m_drag = -1, m_last = 0;
	b2Vec2 m_grab{0.0f, 0.0f};
};
} // namespace

std::unique_ptr<Sample> MakeContactCasesSample()
{
	return std::make_unique<ContactCases>();
}

} // namespace b2a::viewer
