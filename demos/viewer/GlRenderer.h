// b2a_viewer: draws a DrawBatch with OpenGL 3.3 (core profile): one small shader, three
// streamed vertex buffers (triangles, lines, points), as Box2D's testbed does.
#pragma once

#include "Camera.h"
#include "DrawBatch.h"

#include <string>

namespace b2a::viewer
{

/// The OpenGL side of the debug drawing. Create it once a context is current.
class GlRenderer
{
public:
	/// Compile the shader and make the buffers; throws std::runtime_error with the GL log on failure.
	GlRenderer();
	~GlRenderer();
	GlRenderer(const GlRenderer&) = delete;
	GlRenderer& operator=(const GlRenderer&) = delete;

	/// Draw the batch through the camera's projection (triangles, then lines, then points).
	void Draw(const DrawBatch& batch, const Camera& camera);

private:
	void Stream(int list, const std::vector<DrawVertex>& vertices, unsigned mode);
	unsigned m_program = 0;
	int m_projection = -1;
	unsigned m_arrays[3] = {0, 0, 0};
	unsigned m_buffers[3] = {0, 0, 0};
};

/// Compile and link a shader program from its two sources; throws std::runtime_error with the GL
/// log on failure.
unsigned CompileProgram(const char* vertexShader, const char* fragmentShader);

/// Read the default framebuffer (what the window shows) and write it as a PNG, top row first.
/// Returns "" or a message naming the file.
std::string WriteScreenshot(const std::string& path, int width, int height);

} // namespace b2a::viewer
