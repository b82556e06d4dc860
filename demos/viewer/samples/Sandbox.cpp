// b2a_viewer: the sandbox: a box to fill with shapes made in the shape editor (superellipse
// a, b, n, m; ellipse; circle; heart α), previewed where they will appear.
#include "samples/Samples.h"
#include "samples/ShapeEditor.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdio>
#include <random>

namespace b2a::viewer
{
namespace
{
class Sandbox : public Sample
{
public:
	Sandbox()
	{
		MakeWorld(b2Vec2(0.0f, -10.0f));
		const b2Vec2 corners[] = {{-15.0f, 25.0f}, {-15.0f, 0.0f}, {15.0f, 0.0f}, {15.0f, 25.0f}};
		for (int i = 0; i < 3; ++i)
			AddGroundEdge(corners[i], corners[i + 1]);
		// A few to start with, so the box is not empty.
		for (int i = 0; i < 6; ++i)
		{
			m_editor.kind = EditorKind(i % 4);
			m_editor.Make();
			Spawn(b2Vec2(-10.0f + 4.0f * float(i), 3.0f));
		}
		m_editor.kind = EditorKind::superellipse;
		m_editor.Make();
	}

	SampleDefaults Defaults() const override
	{
		return MetreScene(b2Vec2(-16.0f, -1.0f), b2Vec2(16.0f, 27.0f));
	}

	void Draw(DrawBatch& batch, const DrawSettings& draw) override
	{
		Sample::Draw(batch, draw);
		if (!m_editor.shape)
			return;
		// The preview at the spawn point, outline only.
		const auto samples = m_editor.shape->Samples(64);
		std::vector<b2Vec2> outline;
		for (Vec2 v : samples->point)
			outline.push_back(kSpawnPoint + b2Vec2(float(v.x), float(v.y)));
		batch.DrawPolygon(outline.data(), int32(outline.size()), b2Color(0.4f, 0.9f, 1.0f));
	}

	void Panel() override
	{
		if (!ImGui::CollapsingHeader("Shape editor", ImGuiTreeNodeFlags_DefaultOpen))
			return;
		m_editor.Panel();
		if (ImGui::Button("spawn (C)"))
			Spawn(kSpawnPoint);
		ImGui::SameLine();
		ImGui::Text("%d spawned", m_spawned);
	}

	std::map<std::string, double> Readings() const override
	{
		return {{"spawned", m_spawned}};
	}

	bool Keyboard(int key) override
	{
		if (key == GLFW_KEY_C)
		{
			Spawn(kSpawnPoint);
			return true;
		}
		return Sample::Keyboard(key);
	}

private:
	void Spawn(b2Vec2 at)
	{
		if (!m_editor.shape)
			return;
		std::uniform_real_distribution<float> angle(0.0f, 2.0f * b2_pi);
		AddParticle(m_editor.shape, at, angle(m_rng));
		++m_spawned;
	}

	inline static const b2Vec2 kSpawnPoint{0.0f, 20.0f};
	ShapeEditor m_editor;
	int m_spawned = 0;
	std::mt19937 m_rng{7};
};
} // namespace

std::unique_ptr<Sample> MakeSandboxSample()
{
	return std::make_unique<Sandbox>();
}

} // namespace b2a::viewer
