// b2a_viewer: the base of every sample (Box2D testbed's Sample): a world, the mouse joint, the
// bomb, the step with the panel's settings, and the debug drawing through b2a::DrawWorld.
#pragma once

#include "DrawBatch.h"
#include "Settings.h"

#include "b2analytic/Shape.h"

#include <box2d/box2d.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace b2a::viewer
{

/// What a sample asks of the viewer when it starts.
struct SampleDefaults
{
	StepSettings step;                ///< how its world is stepped
	b2Vec2 viewLo{-25.0f, -5.0f};     ///< the box Home shows (world units)
	b2Vec2 viewHi{25.0f, 40.0f};      ///< upper corner of that box
	b2Vec2 boundsLo{-1e3f, -1e3f};    ///< bodies outside [boundsLo, boundsHi] have escaped
	b2Vec2 boundsHi{1e3f, 1e3f};      ///< upper corner of the bounds
	float metre = 1.0f;               ///< world units per metre (1000 for the millimetre scenes)
	float bodySize = 1.0f;            ///< a typical body's width (axes, normals, the bomb)
	float mouseHertz = 5.0f;          ///< the mouse joint's stiffness as a frequency
	float bombDensity = 20.0f;        ///< the bomb's density
	bool polygonTwin = true;          ///< its analytic particles can be switched to Box2D 8-gons
};

/// Defaults of a scene in metres with the testbed's step settings: this view box, and bounds
/// around it `margin` times its size on every side.
SampleDefaults MetreScene(b2Vec2 viewLo, b2Vec2 viewHi, float margin = 2.0f);

/// A sample: a scene in a b2World and what it does with the keys, the mouse and the panel.
class Sample : public b2DestructionListener
{
public:
	~Sample() override;
	Sample(const Sample&) = delete;
	Sample& operator=(const Sample&) = delete;

	/// Camera box, bounds, scales and step defaults.
	virtual SampleDefaults Defaults() const = 0;
	/// The world.
	b2World* World() const { return m_world; }

	/// One frame's stepping: the settings' steps per frame (one step when `singleStep`, none
	/// when paused), then AfterStep after each.
	void Step(const StepSettings& settings, bool paused, bool singleStep);
	/// Steps taken since the start.
	int StepCount() const { return m_stepCount; }
	/// Simulated time since the start.
	double Time() const { return m_time; }
	/// The last step's Box2D profile (milliseconds).
	const b2Profile& LastProfile() const { return m_profile; }

	/// Draw the world (b2a::DrawWorld) and, as the flags ask, contact points, normals and
	/// impulses, the mouse joint's line and the bomb's launch line.
	virtual void Draw(DrawBatch& batch, const DrawSettings& draw);
	/// Lines of text the viewer shows over the scene (time, counts, what the sample measures).
	virtual void Status(std::vector<std::string>& lines) const;
	/// Numbers the sample measures, by name (the report and the tests read them).
	virtual std::map<std::string, double> Readings() const { return {}; }
	/// The sample's own section of the panel (Dear ImGui calls).
	virtual void Panel() {}
	/// A key the viewer does not use itself (GLFW key code); true when the sample used it.
	virtual bool Keyboard(int key);

	/// Left button down at a world point: grab the dynamic body there with a mouse joint.
	/// True when something was grabbed.
	virtual bool MouseDown(b2Vec2 p);
	/// Left button up: release the mouse joint, or launch the bomb being aimed.
	virtual void MouseUp(b2Vec2 p);
	/// The cursor moved (world point): the mouse joint follows it.
	virtual void MouseMove(b2Vec2 p);
	/// Shift and left button down: start aiming a bomb from here.
	void ShiftMouseDown(b2Vec2 p);
	/// Launch a bomb (a Box2D circle, a bullet) from `position` with `velocity`, replacing the last.
	void LaunchBomb(b2Vec2 position, b2Vec2 velocity);
	/// Launch a bomb from above the view at a random spot (the testbed's Space key).
	void LaunchRandomBomb();
	/// The mouse joint, or null.
	b2MouseJoint* MouseJoint() const { return m_mouseJoint; }
	/// The last bomb, or null.
	b2Body* Bomb() const { return m_bomb; }

	/// Switch every analytic fixture to a Box2D polygon with `vertices` corners on its surface
	/// (MakeInscribedPolygon, the benchmarks' baseline), in place: bodies, poses and velocities stay.
	/// Switching back restores the analytic fixtures with their shapes and settings.
	void SwitchToPolygons(bool polygons, int vertices = 8);
	/// True while switched to polygons.
	bool IsPolygons() const { return m_polygons; }

	/// True once after the sample changed its view box (a new case): the viewer shows it.
	bool TakeViewRequest()
	{
		const bool r = m_viewRequest;
		m_viewRequest = false;
		return r;
	}

	/// b2DestructionListener: forget a mouse joint or fixture Box2D destroyed with its body.
	void SayGoodbye(b2Joint* joint) override;
	/// b2DestructionListener: forget a switched fixture destroyed with its body.
	void SayGoodbye(b2Fixture* fixture) override;

protected:
	Sample();
	/// Make and own a world (samples that build their own scene).
	b2World* MakeWorld(b2Vec2 gravity);
	/// Use a world owned elsewhere (a demo scene); it must outlive the sample.
	void UseWorld(b2World* world);
	/// Step the world once (a demo scene steps itself and removes what left through its outlet).
	virtual void StepWorld(float dt, int velocityIterations, int positionIterations);
	/// After each step (a sample's own bookkeeping).
	virtual void AfterStep() {}
	/// Keep a shape so that the fixtures made from it can be switched to polygons and back.
	void RememberShape(const ShapePtr& shape);
	/// A dynamic body with one analytic fixture of `shape` (remembered for the 8-gon switch; made
	/// an 8-gon at once while the sample shows 8-gons).
	b2Body* AddParticle(const ShapePtr& shape, b2Vec2 position, float angle, float density = 1.0f, float friction = 0.6f,
	                    float restitution = 0.0f);
	/// A static body at the origin for the mouse joint and the samples' ground.
	b2Body* GroundBody();
	/// A two-sided edge of the ground body, from a to b.
	b2Fixture* AddGroundEdge(b2Vec2 a, b2Vec2 b, float friction = 0.6f);
	/// Start the clock and the step count again (a sample that loads a new case).
	void ResetClock()
	{
		m_time = 0.0;
		m_stepCount = 0;
	}
	/// Ask the viewer to show the sample's (new) view box.
	void RequestView() { m_viewRequest = true; }

private:
	struct SwitchedFixture;
	void SwitchToPolygon(b2Fixture* analytic);
	std::unique_ptr<b2World> m_ownedWorld;
	b2World* m_world = nullptr;
	b2Body* m_ground = nullptr;
	b2MouseJoint* m_mouseJoint = nullptr;
	b2Body* m_bomb = nullptr;
	bool m_aimingBomb = false;
	b2Vec2 m_bombStart{0.0f, 0.0f};
	b2Vec2 m_mouse{0.0f, 0.0f};
	int m_stepCount = 0;
	double m_time = 0.0;
	b2Profile m_profile{};
	bool m_polygons = false;
	int m_polygonVertices = 8;
	bool m_viewRequest = false;
	std::map<const Shape*, ShapePtr> m_shapes;
	std::map<b2Fixture*, std::unique_ptr<SwitchedFixture>> m_switched; // polygon fixture → what it replaced
};

} // namespace b2a::viewer
