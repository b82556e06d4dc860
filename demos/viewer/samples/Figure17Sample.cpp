// b2a_viewer: the paper's Figure 17 in 3D: two superellipsoids in free flight (the scene of
// b2a_demo_superellipsoids), shaded, until they first touch at the time the 3D time-of-impact
// solver gives, where they stop with the contact point and normal shown. The pair's common
// level, separation and method are solved every frame. Time is in ms, lengths in mm.
#include "samples/Samples.h"

#include "Sample3.h"
#include "common/Figure17Scene.h"

#include "b2analytic/3d/Contact3.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace b2a::viewer
{
namespace
{
// Steps per ms: the pair meets after about 190 steps, three seconds at one step a frame.
constexpr double kStepsPerMs = 1000.0;
// Surface samples per particle's mesh.
constexpr int kMeshSamples = 2000;
const Colour3 kColourI{0.31f, 0.47f, 0.65f, 1.0f}; // the demo's #4e79a7
const Colour3 kColourJ{0.95f, 0.56f, 0.17f, 1.0f}; // the demo's #f28e2b

class Figure17Sample : public Sample3
{
public:
	Figure17Sample() : Sample3(kStepsPerMs), m_scene(demo::MakeFigure17Scene())
	{
		m_toi = TimeOfImpact(*m_scene.a, m_scene.ma, *m_scene.b, m_scene.mb, 1.0);
		m_end = m_toi.Ok() && m_toi.hit ? m_toi.time : 1.0;
		m_box = demo::Figure17SceneBox(m_scene, m_end, 5.0);
		m_meshI = MakeBodyMesh(*m_scene.a, kMeshSamples);
		m_meshJ = MakeBodyMesh(*m_scene.b, kMeshSamples);
		Solve();
	}

	Box3 ViewBox() const override { return m_box; }
	std::vector<Pose3> Bodies() const override { return {m_scene.ma.At(m_t), m_scene.mb.At(m_t)}; }

	void Draw3(MeshBatch& batch, const DrawSettings& draw) const override
	{
		DrawBoxAndAxes(batch, m_box);
		if (draw.shapes)
		{
			DrawBodyMesh(batch, m_meshI, m_scene.ma.At(m_t), kColourI);
			DrawBodyMesh(batch, m_meshJ, m_scene.mb.At(m_t), kColourJ);
		}
		if (!m_contact.Ok())
			return;
		if (AtContact())
		{
			// The contact point and the normal from particle i to particle j, over the meshes.
			DrawArrow3(batch, m_contact.point, m_contact.point + 4.0 * m_contact.normal, Colour3{1.0f, 1.0f, 1.0f, 1.0f});
			batch.AddPoint(m_contact.point, 9.0f, Colour3{1.0f, 0.2f, 0.6f, 1.0f});
		}
		else
		{
			// The gap: the nearest surface points along the normal.
			batch.AddLine(m_contact.pointA, m_contact.pointB, Colour3{0.85f, 0.85f, 0.85f, 1.0f});
			batch.AddPoint(m_contact.pointA, 5.0f, Colour3{0.6f, 0.75f, 1.0f, 1.0f});
			batch.AddPoint(m_contact.pointB, 5.0f, Colour3{1.0f, 0.8f, 0.5f, 1.0f});
		}
	}

	void Status(std::vector<std::string>& lines) const override
	{
		char line[200];
		std::snprintf(line, sizeof(line), "t = %.4f ms, first contact at %.6f ms (the paper: %.4f ms)", m_t, m_end, demo::kFigure17PaperTime);
		lines.push_back(line);
		if (m_contact.Ok())
			std::snprintf(line, sizeof(line), "common level %.4f, separation %.4f mm, %s%s", m_contact.level, m_contact.separation,
			              MethodName(m_contact.method), AtContact() ? ", touching" : "");
		else
			std::snprintf(line, sizeof(line), "contact solve failed: %s", m_contact.failure);
		lines.push_back(line);
	}

	std::map<std::string, double> Readings() const override
	{
		return {{"time_ms", m_t},
		        {"first_contact_ms", m_end},
		        {"common_level", m_contact.level},
		        {"separation_mm", m_contact.separation},
		        {"touching", AtContact() ? 1.0 : 0.0},
		        {"solve_us", m_solveMicros}};
	}

	void Panel() override
	{
		if (!ImGui::CollapsingHeader("Figure 17", ImGuiTreeNodeFlags_DefaultOpen))
			return;
		float t = float(m_t);
		if (ImGui::SliderFloat("t (ms)", &t, 0.0f, float(m_end), "%.4f"))
		{
			m_t = std::clamp(double(t), 0.0, m_end);
			Solve();
		}
		if (ImGui::Button("replay from t = 0"))
		{
			m_t = 0.0;
			Solve();
		}
		ImGui::Text("first contact %.6f ms (paper %.4f)", m_end, demo::kFigure17PaperTime);
		if (!m_contact.Ok())
		{
			ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "contact solve failed: %s", m_contact.failure);
			return;
		}
		ImGui::Text("common level  %.6f", m_contact.level);
		ImGui::Text("separation    %.5f mm", m_contact.separation);
		ImGui::Text("method        %s, %d iterations", MethodName(m_contact.method), m_contact.iterations);
		ImGui::Text("solve time    %.1f us", m_solveMicros);
		if (AtContact())
		{
			const Vec3 p = m_contact.point, n = m_contact.normal;
			ImGui::Text("point  (%.3f, %.3f, %.3f) mm", p.x, p.y, p.z);
			ImGui::Text("normal (%.3f, %.3f, %.3f)", n.x, n.y, n.z);
		}
		ImGui::TextWrapped("i: |x/4|^6 + |y/4|^6 + |z/4|^12 <= 1 (blue); j: |x/2|^8 + |y/3|^8 + |z/2|^8 <= 1 (orange); "
		                   "free flight, stopped at the exact first contact (3D time of impact).");
	}

protected:
	void Advance(double dt) override
	{
		m_t = std::min(m_t + dt, m_end);
		Solve();
	}

private:
	// At (or past) the first contact: the particles touch there, to the solver's tolerance.
	bool AtContact() const { return m_contact.Ok() && (m_contact.touching || (m_toi.hit && m_t >= m_end)); }

	void Solve()
	{
		const auto t0 = std::chrono::steady_clock::now();
		m_contact = ComputeContact(*m_scene.a, m_scene.ma.At(m_t), *m_scene.b, m_scene.mb.At(m_t));
		m_solveMicros = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
	}

	demo::Figure17Scene m_scene;
	TimeOfImpactResult3 m_toi;
	double m_end = 1.0; // the first contact (or the end of the search)
	double m_t = 0.0;
	Box3 m_box;
	BodyMesh m_meshI, m_meshJ;
	ContactResult3 m_contact;
	double m_solveMicros = 0.0;
};
} // namespace

std::unique_ptr<Sample> MakeFigure17Sample()
{
	return std::make_unique<Figure17Sample>();
}

} // namespace b2a::viewer
