// b2analytic: analytic fixtures on Box2D bodies.
//
// An analytic fixture is a b2Fixture whose shape is an internal b2PolygonShape subclass answering
// for the true shape; the library's own b2Contact replaces Box2D's narrow phase for its pairs.
// Why it is built this way (the proxy polygon, the contact registers, continuous collision,
// sensors): docs/design.md, section "The Box2D adapter".
//
// What is allowed:
//  - Create analytic fixtures on dynamic, kinematic and static bodies between steps; destroy them
//    with b2Body::DestroyFixture, their bodies with b2World::DestroyBody, and worlds as usual:
//    everything the adapter holds is released with the fixture. A b2DestructionListener may
//    still read GetAnalyticShape in SayGoodbye(b2Fixture*).
//  - Share one shape among any number of fixtures, bodies and worlds (shapes are immutable); a
//    ShapePtr you hold stays valid after the fixtures, bodies and worlds that used it are gone.
//  - Everything Box2D allows on a fixture: SetDensity + ResetMassData (the mass stays analytic),
//    SetFriction, SetRestitution, SetFilterData, SetSensor, user data, TestPoint, RayCast.
//  - GetAnalyticShape on any fixture (null for plain fixtures and for a null pointer).
// What is refused with an exception (the body and world are left unchanged):
//  - MisuseError: a null body; a locked world (inside b2World::Step, i.e. in any contact
//    listener callback); null arguments to DrawWorld.
//  - InvalidParameter, naming the field and value: a null or too small/too large shape, a
//    non-null def.shape, a non-finite local pose, a negative or non-finite density, friction,
//    restitution or restitution threshold, bad patch parameters, a body whose pose is not finite.
//    Bad shape parameters never get this far: the shape factories refuse them.
//    Inside a Box2D callback, catch what you call: Box2D is not exception-safe, and an
//    exception leaving b2World::Step leaves the world locked.
// What is not allowed and cannot be detected (undefined behaviour, exactly as in Box2D, which
// has no way to tell a dangling pointer from a live one):
//  - using a b2Body* or b2Fixture* after DestroyBody/DestroyFixture or after its world was
//    destroyed, including passing it to CreateAnalyticFixture, GetAnalyticShape or
//    GetAnalyticPose; the const Shape* from GetAnalyticShape lives as long as its fixture (keep
//    your own ShapePtr to outlive it);
//  - changing the proxy polygon through b2Fixture::GetShape() (it must stay as created);
//  - destroying fixtures or bodies inside Step callbacks: Box2D's DestroyFixture/DestroyBody
//    assert on a locked world (or return silently when built without assertions), for analytic
//    fixtures as for its own.
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"

#include <box2d/b2_draw.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_settings.h>

#include <stdexcept>

class b2Body;
class b2World;

namespace b2a
{

/// Thrown when the Box2D API is used in a way the adapter cannot honour (null body, locked world,
/// null arguments).
class MisuseError : public std::logic_error
{
public:
	using std::logic_error::logic_error;
};

/// A contact with an analytic side that touched at the last step keeps touching (one manifold
/// point, its separation positive) while its surfaces stay within this gap; one that did not
/// touch starts at separation zero. Box2D wakes both bodies whenever a contact starts or stops
/// touching, and a grazing contact between two creeping particles of a settled pile would
/// otherwise cross zero by a hundredth of a millimetre step after step and keep the pile awake.
/// A twentieth of Box2D's linear slop (0.25 mm in metres).
constexpr double kContactHoldGap = 0.05 * b2_linearSlop;

/// The hold gap of a contact between a particle that is not convex (a heart) and another such
/// particle or a plain Box2D polygon, edge or chain link: Box2D's linear slop (5 mm in metres). A
/// heart resting in a pile leans on its neighbours by curved lobes, and such a load-bearing
/// contact can drift apart by a few tenths of a millimetre while its bodies are below Box2D's
/// sleep tolerances; once it stops touching, Box2D wakes its island and the load drops for a
/// step, and the pile stays awake (docs/benchmarks.md, "Sleeping piles"). A held contact only
/// stops its surfaces approaching (Box2D's velocity solver has no separation term); the slop is
/// the overlap Box2D itself leaves resting contacts at. Against a convex particle a heart keeps
/// kContactHoldGap: held as far there, mixed piles sleep later (docs/benchmarks.md).
constexpr double kNonConvexHoldGap = b2_linearSlop;

/// The analytic part of a fixture definition.
struct AnalyticFixtureDef
{
	/// The shape (required). Shapes are immutable and may be shared by many fixtures.
	ShapePtr shape;
	/// Pose of the shape in the body's frame (default: at the body origin, unrotated).
	Pose local;
	/// A face of the particle (where two particles touching face to face get two manifold
	/// points, see BuildContactManifold) is the arc within this distance of the tangent at its
	/// flattest point. Default: half of Box2D's linear slop.
	double patchTolerance = 0.5 * b2_linearSlop;
	/// Faces that overlap by less than this fraction of the particle's bounding radius (or than
	/// twice patchTolerance, the slop by default) get one point (see BuildContactManifold). The
	/// default, 0, gives two points wherever two faces overlap by more than the slop; a curved
	/// contact gets one regardless.
	double patchMinWidth = 0.0;
	/// Options of the contact solvers.
	SolverOptions solver;
};

/// Create an analytic fixture on `body`. Every field of `def` is honoured (density, friction,
/// restitution, restitution threshold, filter, sensor flag, user data) except `def.shape`,
/// which must be null: the analytic shape takes its place. With density > 0 the body's mass
/// data comes from the analytic area, centroid and second moment. Throws InvalidParameter for a
/// missing shape, a non-null def.shape, a shape too small for Box2D's tolerances (bounding radius
/// under 0.01) or too large for its float positions (bounding radius plus |local.p| over 4194
/// length units, where a float coordinate is coarser than a tenth of the linear slop) or mass
/// data, a non-finite local pose or body pose, a negative or non-finite density,
/// friction, restitution or restitution threshold, and MisuseError for a null body or a locked
/// world (see "What is allowed" above). `body` must be a live body of a live world.
b2Fixture* CreateAnalyticFixture(b2Body* body, const b2FixtureDef& def, const AnalyticFixtureDef& analytic);

/// Shorthand: an analytic fixture at the body origin with the given density.
b2Fixture* CreateAnalyticFixture(b2Body* body, ShapePtr shape, float density);

/// Shorthand: an analytic fixture at the body origin with the given density, friction and
/// restitution (the rest of b2FixtureDef's defaults), as b2Body::CreateFixture(shape, density)
/// is for Box2D's shapes with friction and restitution set afterwards. Throws as the full form.
b2Fixture* CreateAnalyticFixture(b2Body* body, ShapePtr shape, float density, float friction, float restitution = 0.0f);

/// Shorthand: an analytic fixture as `analytic` says (shape, local pose, patch and solver
/// options) with the given density, friction and restitution (the rest of b2FixtureDef's
/// defaults). Throws as the full form.
b2Fixture* CreateAnalyticFixture(b2Body* body, const AnalyticFixtureDef& analytic, float density, float friction,
                                 float restitution = 0.0f);

/// The analytic shape of a fixture, or null for a plain Box2D fixture.
const Shape* GetAnalyticShape(const b2Fixture* fixture);

/// World pose of a fixture's analytic shape (the body transform times the local pose).
/// Throws InvalidParameter when the fixture is not analytic.
Pose GetAnalyticPose(const b2Fixture* fixture);

/// The analytic contact of two fixtures at their current poses, as the adapter computes it
/// (also for pairs Box2D has no contact for yet). For plain pairs it returns a failed result.
ContactResult ComputeFixtureContact(const b2Fixture* a, const b2Fixture* b);

/// Debug drawing of a whole world through the user's own b2Draw: plain shapes as Box2D draws
/// them, analytic fixtures as their true outlines (hearts included) with `outlineVertices`
/// points, in Box2D's colours; then joints, AABBs, pairs and centres of mass as the draw flags
/// ask (through b2World::DebugDraw with the shape bit cleared). b2World::DebugDraw alone would
/// draw analytic fixtures as their inscribed proxy polygons.
void DrawWorld(b2World* world, b2Draw* draw, int outlineVertices = 48);

} // namespace b2a
