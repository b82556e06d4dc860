// b2a_viewer: the samples, the camera, the keys and the mouse, the stepping and the drawing.
#include "Viewer.h"

#include "SampleRegistry.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

namespace b2a::viewer
{
namespace
{
using Clock = std::chrono::steady_clock;

double Millis(Clock::time_point t0)
{
	return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Contacts are recounted by method every this many frames (the count solves them all again).
constexpr int kCountEvery = 15;

bool Finite(b2Vec2 v)
{
	return std::isfinite(v.x) && std::isfinite(v.y);
}
} // namespace

Viewer::Viewer(Settings& settings) : m_settings(settings)
{
	m_camera.width = m_orbit.width = settings.windowWidth;
	m_camera.height = m_orbit.height = settings.windowHeight;
	const int index = FindSample(settings.sample);
	LoadSample(index >= 0 ? index : 0);
}

Viewer::~Viewer() = default;

void Viewer::LoadSample(int index)
{
	const auto& table = Samples();
	m_index = (index % int(table.size()) + int(table.size())) % int(table.size());
	m_mouseTarget = nullptr;
	m_twin.reset();
	m_sample = table[size_t(m_index)].factory();
	m_sample3 = dynamic_cast<Sample3*>(m_sample.get());
	m_orbiting = false;
	m_defaults = m_sample->Defaults();
	const std::string key = SampleKey(table[size_t(m_index)]);
	m_settings.sample = key;
	if (!m_settings.steps.count(key))
		m_settings.steps[key] = m_defaults.step;
	if (!m_defaults.polygonTwin)
		m_settings.compare = CompareMode::analytic;
	const CompareMode mode = m_settings.compare;
	m_settings.compare = CompareMode::analytic;
	SetCompare(mode);
	m_times = FrameTimes();
	m_recentFrames.clear();
	m_recentSteps.clear();
	m_methods = m_twinMethods = MethodStats();
	m_framesSinceCount = kCountEvery; // count on the first frame
	ResetView();
}

void Viewer::Restart()
{
	const CompareMode mode = m_settings.compare;
	LoadSample(m_index);
	SetCompare(mode);
}

StepSettings& Viewer::Step()
{
	return m_settings.steps[m_settings.sample];
}

b2Vec2 Viewer::TwinOffset() const
{
	return b2Vec2(1.08f * (m_defaults.viewHi.x - m_defaults.viewLo.x), 0.0f);
}

void Viewer::SetCompare(CompareMode mode)
{
	if (!m_defaults.polygonTwin)
		mode = CompareMode::analytic;
	if (mode == m_settings.compare && (mode != CompareMode::sideBySide || m_twin))
		return;
	m_mouseTarget = nullptr;
	if (mode == CompareMode::sideBySide)
	{
		// Both copies start together from the sample's starting state.
		m_sample = Samples()[size_t(m_index)].factory();
		m_sample3 = dynamic_cast<Sample3*>(m_sample.get());
		m_twin = Samples()[size_t(m_index)].factory();
		m_twin->SwitchToPolygons(true);
	}
	else
	{
		m_twin.reset();
		m_sample->SwitchToPolygons(mode == CompareMode::polygons);
	}
	m_settings.compare = mode;
	m_framesSinceCount = kCountEvery;
	ResetView();
}

void Viewer::SetWindowSize(int width, int height)
{
	m_camera.width = m_orbit.width = std::max(width, 1);
	m_camera.height = m_orbit.height = std::max(height, 1);
	m_settings.windowWidth = std::max(width, 200);
	m_settings.windowHeight = std::max(height, 200);
}

void Viewer::ResetView()
{
	if (m_sample3)
	{
		// The starting angles, the box in view left of the panel; turning by itself stays as set.
		OrbitCamera fresh;
		fresh.width = m_orbit.width;
		fresh.height = m_orbit.height;
		fresh.autoOrbit = m_orbit.autoOrbit;
		fresh.orbitPerFrame = m_orbit.orbitPerFrame;
		m_orbit = fresh;
		m_orbit.Fit(m_sample3->ViewBox(), m_settings.showPanel ? kPanelWidth + 20.0f : 0.0f);
		return;
	}
	b2Vec2 hi = m_defaults.viewHi;
	if (m_twin)
		hi += TwinOffset();
	// The scene fits left of the panel.
	m_camera.Fit(m_defaults.viewLo, hi, m_settings.showPanel ? kPanelWidth + 20.0f : 0.0f);
}

Sample* Viewer::SampleAt(b2Vec2 world, b2Vec2& local)
{
	local = world;
	if (m_twin && world.x > m_defaults.viewHi.x + 0.5f * (TwinOffset().x - (m_defaults.viewHi.x - m_defaults.viewLo.x)))
	{
		local = world - TwinOffset();
		return m_twin.get();
	}
	return m_sample.get();
}

void Viewer::OnKey(int key, int action, int mods)
{
	(void)mods;
	if (action == GLFW_RELEASE)
		return;
	if (m_sample3 && OnKey3(key))
		return;
	const float pan = 0.1f * m_camera.halfHeight;
	const bool press = action == GLFW_PRESS;
	switch (key)
	{
	case GLFW_KEY_ESCAPE: m_quit = true; break;
	case GLFW_KEY_LEFT: m_camera.center.x -= pan; break;
	case GLFW_KEY_RIGHT: m_camera.center.x += pan; break;
	case GLFW_KEY_DOWN: m_camera.center.y -= pan; break;
	case GLFW_KEY_UP: m_camera.center.y += pan; break;
	case GLFW_KEY_HOME: ResetView(); break;
	case GLFW_KEY_Z: m_camera.halfHeight *= 1.1f; break;
	case GLFW_KEY_X: m_camera.halfHeight /= 1.1f; break;
	default:
		if (!press)
			break; // the rest act once per press, not on the key's repeat
		switch (key)
		{
		case GLFW_KEY_R: Restart(); break;
		case GLFW_KEY_O: m_singleStep = true; m_settings.pause = true; break;
		case GLFW_KEY_P: m_settings.pause = !m_settings.pause; break;
		case GLFW_KEY_LEFT_BRACKET: LoadSample(m_index - 1); break;
		case GLFW_KEY_RIGHT_BRACKET: LoadSample(m_index + 1); break;
		case GLFW_KEY_TAB: m_settings.showPanel = !m_settings.showPanel; break;
		default:
			m_sample->Keyboard(key);
			if (m_twin)
				m_twin->Keyboard(key);
		}
	}
}

bool Viewer::OnKey3(int key)
{
	// Arrows turn the 3D camera as a 25-pixel drag does; Z and X move it farther and nearer.
	switch (key)
	{
	case GLFW_KEY_LEFT: m_orbit.Orbit(-25.0, 0.0); return true;
	case GLFW_KEY_RIGHT: m_orbit.Orbit(25.0, 0.0); return true;
	case GLFW_KEY_UP: m_orbit.Orbit(0.0, -25.0); return true;
	case GLFW_KEY_DOWN: m_orbit.Orbit(0.0, 25.0); return true;
	case GLFW_KEY_Z: m_orbit.Zoom(1.1); return true;
	case GLFW_KEY_X: m_orbit.Zoom(1.0 / 1.1); return true;
	default: return false;
	}
}

void Viewer::OnMouseButton(int button, int action, int mods)
{
	if (m_sample3)
	{
		// Left drag turns the camera about the scene (the 3D bodies are not dragged).
		if (button == GLFW_MOUSE_BUTTON_LEFT)
			m_orbiting = action == GLFW_PRESS;
		return;
	}
	const b2Vec2 world = m_camera.ScreenToWorld(m_cursor);
	if (button == GLFW_MOUSE_BUTTON_LEFT)
	{
		if (action == GLFW_PRESS)
		{
			b2Vec2 local;
			m_mouseTarget = SampleAt(world, local);
			if (mods & GLFW_MOD_SHIFT)
				m_mouseTarget->ShiftMouseDown(local);
			else
				m_mouseTarget->MouseDown(local);
		}
		else if (action == GLFW_RELEASE && m_mouseTarget)
		{
			m_mouseTarget->MouseUp(m_mouseTarget == m_twin.get() ? world - TwinOffset() : world);
			m_mouseTarget = nullptr;
		}
	}
	else if (button == GLFW_MOUSE_BUTTON_RIGHT)
	{
		m_rightDown = action == GLFW_PRESS;
		m_panAnchor = world;
	}
}

void Viewer::OnCursor(b2Vec2 screen)
{
	const b2Vec2 moved = screen - m_cursor;
	m_cursor = screen;
	if (m_sample3)
	{
		if (m_orbiting)
			m_orbit.Orbit(moved.x, moved.y);
		return;
	}
	const b2Vec2 world = m_camera.ScreenToWorld(screen);
	if (m_rightDown)
	{
		// Keep the world point grabbed under the cursor.
		m_camera.center -= world - m_panAnchor;
		return;
	}
	if (m_mouseTarget)
		m_mouseTarget->MouseMove(m_mouseTarget == m_twin.get() ? world - TwinOffset() : world);
}

void Viewer::OnScroll(double dy)
{
	if (m_sample3)
	{
		m_orbit.Zoom(dy > 0.0 ? 1.0 / 1.1 : 1.1);
		return;
	}
	m_camera.ZoomAbout(m_cursor, dy > 0.0 ? 1.0f / 1.1f : 1.1f);
}

void Viewer::Update()
{
	const auto t0 = Clock::now();
	const StepSettings& s = Step();
	m_sample->Step(s, m_settings.pause, m_singleStep);
	if (m_twin)
		m_twin->Step(s, m_settings.pause, m_singleStep);
	m_singleStep = false;
	m_times.step = Millis(t0);
	if (m_sample3 && !m_orbiting)
		m_orbit.Advance();
	if (m_sample->TakeViewRequest())
	{
		m_defaults = m_sample->Defaults();
		ResetView();
	}
	if (m_settings.countMethods && ++m_framesSinceCount >= kCountEvery)
		CountMethodsNow();
}

void Viewer::CountMethodsNow()
{
	m_methods = CountMethods(m_sample->World());
	m_twinMethods = m_twin ? CountMethods(m_twin->World()) : MethodStats();
	m_framesSinceCount = 0;
}

void Viewer::DrawScene()
{
	const auto t0 = Clock::now();
	m_batch.Clear();
	m_batch3.Clear();
	if (m_sample3)
	{
		m_sample3->Draw3(m_batch3, m_settings.draw);
		m_times.draw = Millis(t0);
		return;
	}
	m_batch.SetOffset(b2Vec2(0.0f, 0.0f));
	// About one outline point per 2.5 pixels of a typical body's circumference, 12 to 48.
	const float pixels = m_defaults.bodySize / m_camera.UnitsPerPixel();
	m_batch.SetOutlineVertices(std::clamp(int(std::lround(b2_pi * pixels / 2.5f)), 12, 48));
	m_sample->Draw(m_batch, m_settings.draw);
	if (m_twin)
	{
		m_batch.SetOffset(TwinOffset());
		m_twin->Draw(m_batch, m_settings.draw);
		m_batch.SetOffset(b2Vec2(0.0f, 0.0f));
	}
	m_times.draw = Millis(t0);
}

void Viewer::RecordFrameTime(double ms, double renderMs)
{
	m_times.frame = ms;
	m_times.render = renderMs;
	m_times.totalRender += renderMs;
	m_recentFrames.push_back(ms);
	m_recentSteps.push_back(m_times.step);
	if (m_recentFrames.size() > 60)
	{
		m_recentFrames.erase(m_recentFrames.begin());
		m_recentSteps.erase(m_recentSteps.begin());
	}
	const double n = double(m_recentFrames.size());
	m_times.meanFrame = std::accumulate(m_recentFrames.begin(), m_recentFrames.end(), 0.0) / n;
	m_times.meanStep = std::accumulate(m_recentSteps.begin(), m_recentSteps.end(), 0.0) / n;
	m_times.maxFrame = *std::max_element(m_recentFrames.begin(), m_recentFrames.end());
	++m_times.frames;
	m_times.totalFrame += ms;
	m_times.totalStep += m_times.step;
	m_times.totalDraw += m_times.draw;
	m_times.worstFrame = std::max(m_times.worstFrame, ms);
}

WorldHealth Viewer::Health() const
{
	WorldHealth h;
	if (m_sample3)
	{
		// The bodies' poses: finite, and their centres within the view box grown by its size.
		const Box3 box = m_sample3->ViewBox();
		const Vec3 margin = box.upper - box.lower;
		for (const Pose3& pose : m_sample3->Bodies())
		{
			++h.bodies;
			if (!IsValidPose(pose))
				++h.nonFinite;
			else
				for (int i = 0; i < 3; ++i)
					if (pose.p[i] < box.lower[i] - margin[i] || pose.p[i] > box.upper[i] + margin[i])
					{
						++h.escaped;
						break;
					}
		}
	}
	for (const Sample* s : {m_sample.get(), m_twin.get()})
	{
		if (!s)
			continue;
		for (const b2Body* b = s->World()->GetBodyList(); b; b = b->GetNext())
		{
			++h.bodies;
			const b2Vec2 p = b->GetPosition();
			if (!Finite(p) || !std::isfinite(b->GetAngle()) || !Finite(b->GetLinearVelocity()) ||
			    !std::isfinite(b->GetAngularVelocity()))
				++h.nonFinite;
			else if (p.x < m_defaults.boundsLo.x || p.y < m_defaults.boundsLo.y || p.x > m_defaults.boundsHi.x ||
			         p.y > m_defaults.boundsHi.y)
				++h.escaped;
		}
	}
	return h;
}

std::vector<b2Vec2> Viewer::BodyScreenPoints() const
{
	std::vector<b2Vec2> points;
	if (m_sample3)
		for (const Pose3& pose : m_sample3->Bodies())
		{
			double depth = 0.0;
			const b2Vec2 p = m_orbit.WorldToScreen(pose.p, &depth);
			if (depth > 0.0)
				points.push_back(p);
		}
	for (const Sample* s : {m_sample.get(), m_twin.get()})
	{
		if (!s)
			continue;
		const b2Vec2 offset = s == m_twin.get() ? TwinOffset() : b2Vec2(0.0f, 0.0f);
		for (const b2Body* b = s->World()->GetBodyList(); b; b = b->GetNext())
		{
			if (b->GetType() == b2_staticBody)
				continue;
			const b2Vec2 c = b->GetWorldCenter();
			bool inside = false;
			for (const b2Fixture* f = b->GetFixtureList(); f && !inside; f = f->GetNext())
				inside = f->TestPoint(c);
			if (inside)
				points.push_back(m_camera.WorldToScreen(c + offset));
		}
	}
	return points;
}

} // namespace b2a::viewer
