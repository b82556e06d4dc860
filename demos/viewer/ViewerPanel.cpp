// b2a_viewer: the panel (Dear ImGui): samples, stepping, drawing, comparison with Box2D's
// 8-gons, statistics and Box2D's profile; and the text over the scene.
#include "SampleRegistry.h"
#include "Viewer.h"

#include "b2analytic/Math.h" // kPi

#include <imgui.h>

#include <cstdio>
#include <string>

namespace b2a::viewer
{
namespace
{
void MethodTable(const char* id, const MethodStats& stats)
{
	if (!ImGui::BeginTable(id, 4, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp))
		return;
	ImGui::TableSetupColumn("method");
	ImGui::TableSetupColumn("pairs");
	ImGui::TableSetupColumn("touch");
	ImGui::TableSetupColumn("us each");
	ImGui::TableHeadersRow();
	for (const auto& [name, t] : stats.methods)
	{
		ImGui::TableNextRow();
		ImGui::TableNextColumn();
		ImGui::TextUnformatted(name.c_str());
		ImGui::TableNextColumn();
		ImGui::Text("%d", t.contacts);
		ImGui::TableNextColumn();
		ImGui::Text("%d", t.touching);
		ImGui::TableNextColumn();
		ImGui::Text("%.2f", t.Mean());
	}
	ImGui::EndTable();
	if (stats.failed > 0)
		ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%d solves failed", stats.failed);
}

void WorldCounts(b2World* w)
{
	ImGui::Text("bodies %d, contacts %d, joints %d", w->GetBodyCount(), w->GetContactCount(), w->GetJointCount());
	ImGui::Text("proxies %d, tree height %d, balance %d", w->GetProxyCount(), w->GetTreeHeight(), w->GetTreeBalance());
}

void ProfileRow(const char* name, float ms)
{
	ImGui::Text("%-15s %8.3f ms", name, ms);
}
} // namespace

void Viewer::Panel()
{
	TextOverlay();
	if (!m_settings.showPanel)
	{
		m_panelRect[0] = m_panelRect[1] = m_panelRect[2] = m_panelRect[3] = 0.0f;
		return;
	}
	ImGui::SetNextWindowPos(ImVec2(float(m_camera.width) - kPanelWidth - 10.0f, 10.0f));
	ImGui::SetNextWindowSize(ImVec2(kPanelWidth, float(m_camera.height) - 20.0f));
	ImGui::Begin("b2a_viewer", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
	const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
	m_panelRect[0] = pos.x;
	m_panelRect[1] = pos.y;
	m_panelRect[2] = size.x;
	m_panelRect[3] = size.y;
	PanelContents();
	ImGui::End();
}

void Viewer::PanelContents()
{
	const auto& table = Samples();
	const std::string current = std::string(table[size_t(m_index)].category) + " / " + table[size_t(m_index)].name;
	ImGui::SetNextItemWidth(-1.0f);
	if (ImGui::BeginCombo("##sample", current.c_str()))
	{
		for (size_t i = 0; i < table.size(); ++i)
		{
			const std::string label = std::string(table[i].category) + " / " + table[i].name;
			if (ImGui::Selectable(label.c_str(), int(i) == m_index))
				LoadSample(int(i));
		}
		ImGui::EndCombo();
	}
	m_sample->Panel();
	if (m_sample3)
		CameraPanel3();

	if (ImGui::CollapsingHeader("Step", ImGuiTreeNodeFlags_DefaultOpen))
	{
		StepSettings& s = Step();
		StepSettings edit = s;
		// A 3D sample steps its own bodies: only the rate and the steps per frame apply.
		if (m_sample3)
			ImGui::SetNextItemWidth(120.0f);
		ImGui::InputDouble(m_sample3 ? "steps per time unit" : "Hz", &edit.hertz, 0.0, 0.0, "%.0f");
		if (!m_sample3)
		{
			ImGui::SliderInt("velocity iterations", &edit.velocityIterations, 1, 50);
			ImGui::SliderInt("position iterations", &edit.positionIterations, 0, 50);
		}
		if (m_sample3)
			ImGui::SetNextItemWidth(120.0f);
		ImGui::SliderInt("steps per frame", &edit.stepsPerFrame, 1, 50);
		if (!m_sample3)
		{
			ImGui::Checkbox("sleep", &edit.sleep);
			ImGui::Checkbox("warm starting", &edit.warmStarting);
			ImGui::Checkbox("time of impact", &edit.continuous);
		}
		// A typed value out of range is refused with the reason, never clamped.
		if (const std::string why = CheckStepSettings(edit); why.empty())
		{
			if (edit.hertz != s.hertz)
				m_stepError.clear();
			s = edit;
		}
		else
			m_stepError = why;
		if (!m_stepError.empty())
			ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "refused: %s", m_stepError.c_str());
		ImGui::Checkbox("pause (P)", &m_settings.pause);
		ImGui::SameLine();
		if (ImGui::Button("step (O)"))
			m_singleStep = m_settings.pause = true;
		ImGui::SameLine();
		if (ImGui::Button("restart (R)"))
			Restart();
		ImGui::SameLine();
		if (ImGui::Button("defaults"))
			s = m_defaults.step;
	}

	if (m_defaults.polygonTwin && ImGui::CollapsingHeader("Analytic or Box2D 8-gons", ImGuiTreeNodeFlags_DefaultOpen))
	{
		int mode = int(m_settings.compare);
		ImGui::RadioButton("analytic", &mode, int(CompareMode::analytic));
		ImGui::SameLine();
		ImGui::RadioButton("8-gons", &mode, int(CompareMode::polygons));
		ImGui::SameLine();
		ImGui::RadioButton("side by side", &mode, int(CompareMode::sideBySide));
		if (mode != int(m_settings.compare))
			SetCompare(CompareMode(mode));
	}

	if (ImGui::CollapsingHeader("Draw"))
	{
		DrawSettings& d = m_settings.draw;
		ImGui::Checkbox("shapes", &d.shapes);
		if (!m_sample3) // the rest are Box2D's (a 3D sample has no Box2D bodies)
		{
			ImGui::Checkbox("joints", &d.joints);
			ImGui::Checkbox("AABBs", &d.aabbs);
			ImGui::Checkbox("contact points", &d.contactPoints);
			ImGui::Checkbox("contact normals", &d.contactNormals);
			ImGui::Checkbox("contact impulses", &d.contactImpulses);
			ImGui::Checkbox("centres of mass", &d.centresOfMass);
		}
		ImGui::Checkbox("statistics", &d.statistics);
		if (!m_sample3)
			ImGui::Checkbox("profile", &d.profile);
	}
	if (m_settings.draw.statistics)
		StatisticsPanel();
	if (!m_sample3 && m_settings.draw.profile && ImGui::CollapsingHeader("Box2D profile (last step)", ImGuiTreeNodeFlags_DefaultOpen))
	{
		const b2Profile& p = m_sample->LastProfile();
		ProfileRow("step", p.step);
		ProfileRow("collide", p.collide);
		ProfileRow("solve", p.solve);
		ProfileRow("solve init", p.solveInit);
		ProfileRow("solve velocity", p.solveVelocity);
		ProfileRow("solve position", p.solvePosition);
		ProfileRow("solve TOI", p.solveTOI);
		ProfileRow("broad-phase", p.broadphase);
	}
	if (ImGui::CollapsingHeader("Keys and mouse"))
		ImGui::TextWrapped(m_sample3 ? "P pause, O single step, R restart, [ ] previous and next sample, Home reset view, left drag or "
		                               "arrows turn the camera about the scene, the wheel or Z X move it nearer and farther, Tab "
		                               "hides the panel, Esc quits." :
		                               "P pause, O single step, R restart, [ ] previous and next sample, Home reset view, arrows pan, "
		                   "Z X or the wheel zoom, right drag pans, left drag moves a body, Shift and left drag launches a "
		                   "bomb (Space drops one), Tab hides the panel, Esc quits.");
}

void Viewer::StatisticsPanel()
{
	if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen))
		return;
	const FrameTimes& t = m_times;
	ImGui::Text("frame %.1f ms (mean %.1f, max %.1f)", t.frame, t.meanFrame, t.maxFrame);
	ImGui::Text("step %.1f ms, draw %.1f ms, render %.1f ms", t.meanStep, t.draw, t.render);
	if (m_sample3)
	{
		ImGui::Text("%d shaded triangles", int(m_batch3.Triangles().size() / 3));
		return; // no Box2D world to count, no Box2D contacts to count by method
	}
	WorldCounts(m_sample->World());
	if (m_twin)
	{
		ImGui::TextUnformatted("8-gons:");
		WorldCounts(m_twin->World());
	}
	ImGui::Checkbox("count contacts by method", &m_settings.countMethods);
	if (!m_settings.countMethods)
		return;
	ImGui::TextWrapped("pairs solved again after the step, cold, every few frames:");
	MethodTable("methods", m_methods);
	if (m_twin)
	{
		ImGui::TextUnformatted("8-gons:");
		MethodTable("twin_methods", m_twinMethods);
	}
}

void Viewer::CameraPanel3()
{
	if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
		return;
	ImGui::Checkbox("turn by itself", &m_orbit.autoOrbit);
	float degrees = float(m_orbit.orbitPerFrame * 180.0 / kPi);
	ImGui::SetNextItemWidth(120.0f);
	if (ImGui::SliderFloat("degrees a frame", &degrees, -2.0f, 2.0f, "%.2f"))
		m_orbit.orbitPerFrame = double(degrees) * kPi / 180.0;
	if (ImGui::Button("reset view (Home)"))
		ResetView();
	ImGui::TextWrapped("Left drag turns the camera about the scene, the wheel moves it nearer or farther.");
}

void Viewer::TextOverlay()
{
	ImDrawList* list = ImGui::GetBackgroundDrawList();
	std::vector<std::string> lines;
	const SampleEntry& e = Samples()[size_t(m_index)];
	lines.push_back(std::string(e.category) + " / " + e.name + (m_settings.pause ? "   (paused)" : ""));
	m_sample->Status(lines);
	if (m_twin)
	{
		lines.push_back("right: the same scene with Box2D 8-gons");
		m_twin->Status(lines);
	}
	float y = 8.0f;
	for (const std::string& line : lines)
	{
		list->AddText(ImVec2(10.0f, y), IM_COL32(230, 230, 230, 255), line.c_str());
		y += ImGui::GetTextLineHeightWithSpacing();
	}
}

} // namespace b2a::viewer
