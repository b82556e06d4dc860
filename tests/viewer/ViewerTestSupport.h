// b2analytic tests: helpers of the viewer's tests.
#pragma once

#include "SampleRegistry.h"
#include "Viewer.h"

#include <box2d/box2d.h>

#include <string>
#include <vector>

namespace b2a::test
{

/// A viewer on its own settings, started on the sample with this key (1280 × 800 window).
struct TestViewer
{
	viewer::Settings settings;
	std::unique_ptr<viewer::Viewer> view;

	explicit TestViewer(const std::string& sample)
	{
		settings.sample = sample;
		view = std::make_unique<viewer::Viewer>(settings);
	}
	/// The sample's world.
	b2World* World() { return view->Current().World(); }
	/// Run frames.
	void Frames(int n)
	{
		for (int i = 0; i < n; ++i)
			view->Update();
	}
	/// The dynamic bodies, in the world's order.
	std::vector<b2Body*> Dynamic()
	{
		std::vector<b2Body*> out;
		for (b2Body* b = World()->GetBodyList(); b; b = b->GetNext())
			if (b->GetType() == b2_dynamicBody)
				out.push_back(b);
		return out;
	}
	/// Press and release a key, as GLFW reports it.
	void Key(int key, int mods = 0)
	{
		view->OnKey(key, 1 /* GLFW_PRESS */, mods);
		view->OnKey(key, 0 /* GLFW_RELEASE */, mods);
	}
	/// Move the cursor to a world point.
	void CursorAt(b2Vec2 world) { view->OnCursor(view->View().WorldToScreen(world)); }
};

} // namespace b2a::test
