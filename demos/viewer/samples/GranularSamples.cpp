// b2a_viewer: the demos' granular scenes (demos/common/GranularScene) in millimetres: the
// hopper discharge, the packing and the Beverloo channel, with the demos' time step and units.
#include "samples/Samples.h"

#include "common/GranularScene.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace b2a::viewer
{
namespace
{
// What differs between the three scenes.
struct GranularSetup
{
	demo::GranularConfig config;
	double openAt = -1.0;   // simulated time at which the outlet opens by itself (< 0: never)
	float viewTop = 100.0f; // top of the view (mm)
};

class GranularSample : public Sample
{
public:
	explicit GranularSample(const GranularSetup& setup) : m_setup(setup), m_scene(setup.config)
	{
		UseWorld(&m_scene.World());
		for (const demo::ParticleState& p : m_scene.SaveState())
			RememberShape(p.shape);
	}

	SampleDefaults Defaults() const override
	{
		const demo::GranularConfig& c = m_setup.config;
		SampleDefaults d;
		d.step.hertz = 1.0 / c.dt;
		d.step.velocityIterations = c.velocityIterations;
		d.step.positionIterations = c.positionIterations;
		d.step.stepsPerFrame = 5;
		d.step.sleep = false; // the demos never let particles sleep
		const float w = float(0.5 * c.boxWidth);
		d.viewLo = b2Vec2(-w - 2.0f, -float(4.0 * c.width));
		d.viewHi = b2Vec2(w + 2.0f, m_setup.viewTop);
		// GranularScene removes what falls 2 widths below the outlet; anything else outside the
		// container has escaped through a wall.
		d.boundsLo = b2Vec2(-w - float(c.width), -float(3.0 * c.width));
		d.boundsHi = b2Vec2(w + float(c.width), float(c.boxHeight + 10.0 * c.width));
		d.metre = 1000.0f;
		d.bodySize = float(c.width);
		d.mouseHertz = 100.0f;
		d.bombDensity = float(20.0 * c.density);
		return d;
	}

	void Status(std::vector<std::string>& lines) const override
	{
		Sample::Status(lines);
		const demo::Energies e = m_scene.ComputeEnergies();
		char line[200];
		std::snprintf(line, sizeof(line), "%d particles in the container, %d discharged; outlet %s", m_scene.Remaining(),
		              m_scene.Discharged(), m_setup.config.outletWidth <= 0.0 ? "none" : m_open ? "open" : "closed (G opens it)");
		lines.push_back(line);
		std::snprintf(line, sizeof(line), "kinetic energy %.3g uJ (translational %.3g, rotational %.3g), packing fraction %.3f",
		              e.translational + e.rotational, e.translational, e.rotational, m_scene.PackingFraction());
		lines.push_back(line);
	}

	std::map<std::string, double> Readings() const override
	{
		const demo::Energies e = m_scene.ComputeEnergies();
		return {{"remaining", m_scene.Remaining()},
		        {"discharged", m_scene.Discharged()},
		        {"kinetic_energy", e.translational + e.rotational},
		        {"open", m_open ? 1.0 : 0.0}};
	}

	void Panel() override
	{
		if (m_setup.config.outletWidth > 0.0 && !m_open && ImGui::Button("Open the outlet (G)"))
			Open();
	}

	bool Keyboard(int key) override
	{
		if (key == GLFW_KEY_G && m_setup.config.outletWidth > 0.0)
		{
			Open();
			return true;
		}
		return Sample::Keyboard(key);
	}

protected:
	void StepWorld(float dt, int velocityIterations, int positionIterations) override
	{
		m_scene.Step(dt, velocityIterations, positionIterations);
	}

	void AfterStep() override
	{
		if (!m_open && m_setup.openAt >= 0.0 && m_scene.Time() >= m_setup.openAt)
			Open();
	}

private:
	void Open()
	{
		if (m_setup.config.outletWidth > 0.0)
			m_scene.OpenOutlet();
		m_open = true;
	}

	GranularSetup m_setup;
	demo::GranularScene m_scene;
	bool m_open = false;
};
} // namespace

std::unique_ptr<Sample> MakeHopperSample()
{
	// The hopper demo's container (60 mm, outlet of 12 particle widths) with fewer particles, so
	// that five of its 0.2 ms steps a frame stay interactive on two cores.
	GranularSetup s;
	s.config.particles = 400;
	s.config.boxWidth = 60.0;
	s.config.outletWidth = 12.0 * s.config.width;
	s.openAt = 0.25;
	s.viewTop = 45.0f;
	return std::make_unique<GranularSample>(s);
}

std::unique_ptr<Sample> MakePackingSample()
{
	// The packing demo's closed 40 mm box.
	GranularSetup s;
	s.config.particles = 300;
	s.config.boxWidth = 40.0;
	s.config.outletWidth = 0.0;
	s.viewTop = 60.0f;
	return std::make_unique<GranularSample>(s);
}

std::unique_ptr<Sample> MakeBeverlooSample()
{
	// The Beverloo demo's 2 x 0.66 mm ellipses in its quick 30 mm channel, outlet of 6 major axes.
	GranularSetup s;
	demo::GranularConfig& c = s.config;
	c = demo::BeverlooEllipses();
	c.boxWidth = 30.0;
	c.boxHeight = 150.0;
	c.particles = 500;
	c.outletWidth = 6.0 * c.width;
	s.openAt = 0.2;
	s.viewTop = 50.0f; // the settled bed; the lattice starts above it and falls in
	return std::make_unique<GranularSample>(s);
}

} // namespace b2a::viewer
