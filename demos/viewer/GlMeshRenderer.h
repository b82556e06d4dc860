// b2a_viewer: draws a 3D sample's MeshBatch with OpenGL 3.3 (core profile) through the orbiting
// camera: the triangles with Lambert shading and a depth buffer, then the lines and points that
// go over the scene.
#pragma once

#include "MeshBatch.h"
#include "OrbitCamera.h"

namespace b2a::viewer
{

/// The OpenGL side of the 3D drawing. Create it once a context is current.
class GlMeshRenderer
{
public:
	/// Compile the shader and make the buffers; throws std::runtime_error with the GL log on failure.
	GlMeshRenderer();
	~GlMeshRenderer();
	GlMeshRenderer(const GlMeshRenderer&) = delete;
	GlMeshRenderer& operator=(const GlMeshRenderer&) = delete;

	/// Draw the batch (nothing when it is empty); clears the depth buffer first.
	void Draw(const MeshBatch& batch, const OrbitCamera& camera);

private:
	void Stream(const std::vector<MeshVertex>& vertices, unsigned mode);
	unsigned m_program = 0;
	int m_viewProjection = -1;
	int m_light = -1;
	unsigned m_array = 0;
	unsigned m_buffer = 0;
};

} // namespace b2a::viewer
