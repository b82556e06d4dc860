// b2a_viewer: the application without the window: the samples, the camera, the keys and the
// mouse (the GLFW callbacks call OnKey, OnMouseButton, OnCursor and OnScroll, and so do the
// tests), the stepping, the drawing into a DrawBatch and the panel (Dear ImGui).
#pragma once

#include "Camera.h"
#include "DrawBatch.h"
#include "MeshBatch.h"
#include "MethodStats.h"
#include "OrbitCamera.h"
#include "Sample.h"
#include "Sample3.h"
#include "Settings.h"

#include <memory>
#include <string>
#include <vector>

namespace b2a::viewer
{

/// Whether the scene is sound: no NaN, nothing escaped.
struct WorldHealth
{
	int bodies = 0;    ///< bodies in the world(s)
	int nonFinite = 0; ///< bodies with a non-finite position, angle or velocity
	int escaped = 0;   ///< bodies outside the sample's bounds
};

/// Frame times in milliseconds, over the last frames and since the sample started.
struct FrameTimes
{
	double frame = 0.0;     ///< the whole last frame (stepping, drawing, the panel, the swap)
	double step = 0.0;      ///< the last frame's stepping
	double draw = 0.0;      ///< the last frame's DrawScene
	double render = 0.0;    ///< the last frame's OpenGL drawing, Dear ImGui's included, and the buffer swap
	double meanFrame = 0.0; ///< mean over the last 60 frames
	double meanStep = 0.0;  ///< mean stepping over the last 60 frames
	double maxFrame = 0.0;  ///< slowest of the last 60 frames
	int frames = 0;         ///< frames since the sample started
	double totalFrame = 0.0; ///< sum of all frame times since the sample started
	double totalStep = 0.0;  ///< sum of all stepping times since the sample started
	double totalDraw = 0.0;  ///< sum of all drawing times since the sample started
	double totalRender = 0.0; ///< sum of all rendering times since the sample started
	double worstFrame = 0.0; ///< slowest frame since the sample started
};

/// The viewer's state and behaviour, independent of GLFW's window and OpenGL.
class Viewer
{
public:
	/// A viewer on these settings (kept by reference: the panel changes them). Loads the
	/// settings' sample, or the first.
	explicit Viewer(Settings& settings);
	~Viewer();

	/// Load sample `index` of Samples() in its starting state, with its step settings (kept per
	/// sample in the settings) and its view.
	void LoadSample(int index);
	/// Load the sample again (R).
	void Restart();
	/// Index of the current sample.
	int SampleIndex() const { return m_index; }
	/// The current sample (the analytic one when side by side).
	Sample& Current() { return *m_sample; }
	/// The current sample as a 3D sample, or null (2D samples).
	Sample3* Current3() { return m_sample3; }
	/// The 8-gon copy shown side by side, or null.
	Sample* Twin() { return m_twin.get(); }
	/// Where the twin is drawn relative to the sample.
	b2Vec2 TwinOffset() const;
	/// The settings (the panel's state).
	const Settings& GetSettings() const { return m_settings; }
	/// The current sample's defaults.
	const SampleDefaults& Defaults() const { return m_defaults; }
	/// The current sample's step settings (the panel edits them).
	StepSettings& Step();
	/// Show analytic particles, Box2D 8-gons in their place, or both side by side.
	void SetCompare(CompareMode mode);

	/// The camera.
	Camera& View() { return m_camera; }
	/// The 3D samples' camera (window size kept with the 2D camera's).
	OrbitCamera& Orbit() { return m_orbit; }
	/// The window's size in pixels.
	void SetWindowSize(int width, int height);
	/// Show the sample's view box (Home).
	void ResetView();

	/// A key event (GLFW key, action and modifier codes).
	void OnKey(int key, int action, int mods);
	/// A mouse button event at the last cursor position (GLFW codes).
	void OnMouseButton(int button, int action, int mods);
	/// The cursor moved to a screen point (pixels from the top-left corner).
	void OnCursor(b2Vec2 screen);
	/// The wheel turned: zoom about the cursor (3D: move the camera nearer or farther).
	void OnScroll(double dy);
	/// Esc was pressed.
	bool QuitRequested() const { return m_quit; }

	/// Step the sample(s) as the settings say (paused, single step, steps per frame).
	void Update();
	/// Draw the scene(s) into the batch.
	void DrawScene();
	/// The panel and the text over the scene (Dear ImGui; between ImGui::NewFrame and Render).
	void Panel();
	/// Record the whole last frame's duration and the part of it spent rendering (main measures them).
	void RecordFrameTime(double milliseconds, double renderMilliseconds = 0.0);
	/// What DrawScene drew.
	const DrawBatch& Batch() const { return m_batch; }
	/// What DrawScene drew of a 3D sample (empty for 2D samples).
	const MeshBatch& Batch3() const { return m_batch3; }
	/// Frame times.
	const FrameTimes& Times() const { return m_times; }
	/// The panel's rectangle in pixels (x, y, width, height), or zero when hidden.
	const float* PanelRect() const { return m_panelRect; }
	/// The contacts counted by method (refreshed every few frames while enabled).
	const MethodStats& Methods(bool twin = false) const { return twin ? m_twinMethods : m_methods; }
	/// Recount the contacts by method now.
	void CountMethodsNow();

	/// NaN and escape check of the world(s).
	WorldHealth Health() const;
	/// Screen points of the moving (dynamic and kinematic) bodies' centres of mass that lie inside
	/// their own fixtures (3D: the bodies' centres in front of the camera).
	std::vector<b2Vec2> BodyScreenPoints() const;

	/// The panel's width in pixels.
	static constexpr float kPanelWidth = 330.0f;
	/// The background colour the renderer clears to.
	static constexpr float kBackground[3] = {0.15f, 0.15f, 0.17f};

private:
	Sample* SampleAt(b2Vec2 world, b2Vec2& local);
	void PanelContents();
	void StatisticsPanel();
	void TextOverlay();
	void CameraPanel3();
	bool OnKey3(int key);
	Settings& m_settings;
	int m_index = 0;
	std::unique_ptr<Sample> m_sample, m_twin;
	Sample3* m_sample3 = nullptr; // m_sample when it is a 3D sample
	SampleDefaults m_defaults;
	Camera m_camera;
	DrawBatch m_batch;
	OrbitCamera m_orbit;
	MeshBatch m_batch3;
	bool m_orbiting = false; // left drag turns the 3D camera
	FrameTimes m_times;
	std::vector<double> m_recentFrames, m_recentSteps;
	MethodStats m_methods, m_twinMethods;
	int m_framesSinceCount = 0;
	bool m_singleStep = false;
	bool m_quit = false;
	bool m_rightDown = false;
	b2Vec2 m_cursor{0.0f, 0.0f};
	b2Vec2 m_panAnchor{0.0f, 0.0f};
	Sample* m_mouseTarget = nullptr;
	float m_panelRect[4] = {0.0f, 0.0f, 0.0f, 0.0f};
	std::string m_stepError; // why the last typed step setting was refused
};

} // namespace b2a::viewer
