// b2a_viewer: the base of the 3D samples. Box2D is 2D, so a 3D sample keeps its own bodies and
// steps them itself; its world stays empty (the viewer's stepping, pause and restart work as for
// every sample), and it draws into a MeshBatch that the mesh renderer shows through the
// orbiting camera, not through b2Draw.
#pragma once

#include "MeshBatch.h"
#include "Sample.h"

#include "b2analytic/3d/Shape3.h"

#include <array>
#include <vector>

namespace b2a::viewer
{

/// A shape's surface as a triangle mesh in its body frame, with the unit normal of the level
/// set (its gradient) at each vertex for smooth shading.
struct BodyMesh
{
	std::vector<Vec3> vertex;                 ///< body-frame positions on the surface
	std::vector<Vec3> normal;                 ///< outward unit normals there
	std::vector<std::array<int, 3>> triangle; ///< vertex indices
};

/// The mesh of a shape's surface from about `samples` of its surface samples (the demos'
/// SurfaceMesh: rings of the shape's parametrisation, quads split in two, fans at the poles).
BodyMesh MakeBodyMesh(const Shape3& shape, int samples);

/// Add the mesh at a pose to the batch, shaded in colour c.
void DrawBodyMesh(MeshBatch& batch, const BodyMesh& mesh, const Pose3& pose, const Colour3& c);

/// An arrow from `from` to `to` over the scene: its shaft and a head of four lines.
void DrawArrow3(MeshBatch& batch, Vec3 from, Vec3 to, const Colour3& c);

/// The twelve edges of a box (dim), and its three axes from the lower corner in red, green and blue.
void DrawBoxAndAxes(MeshBatch& batch, const Box3& box);

/// A sample whose bodies are 3D particles the sample moves itself.
class Sample3 : public Sample
{
public:
	/// No 8-gon twin; the step settings' rate is the sample's (steps per unit of its time).
	SampleDefaults Defaults() const override;
	/// Nothing in 2D.
	void Draw(DrawBatch& batch, const DrawSettings& draw) override;
	/// No bombs: Space does nothing.
	bool Keyboard(int key) override;

	/// Draw the scene into the batch.
	virtual void Draw3(MeshBatch& batch, const DrawSettings& draw) const = 0;
	/// The box the camera shows (Home).
	virtual Box3 ViewBox() const = 0;
	/// The bodies' poses (their centres are checked on the screen, their values for NaN).
	virtual std::vector<Pose3> Bodies() const = 0;

protected:
	/// A sample stepped `hertz` times per unit of its own time, with an empty world.
	explicit Sample3(double hertz);
	/// Advance the bodies by dt (the viewer's step; the empty world is not stepped).
	virtual void Advance(double dt) = 0;

private:
	void StepWorld(float dt, int velocityIterations, int positionIterations) final;
	double m_hertz;
};

} // namespace b2a::viewer
