// b2a_viewer: OpenGL drawing of the 3D samples' meshes.
#include "GlMeshRenderer.h"

#include "GlRenderer.h" // CompileProgram

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>

namespace b2a::viewer
{
namespace
{
const char* kVertexShader = R"(#version 330
uniform mat4 viewProjection;
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
layout(location = 3) in float size;
out vec3 fragmentNormal;
out vec4 fragmentColor;
void main()
{
	gl_Position = viewProjection * vec4(position, 1.0);
	gl_PointSize = size;
	fragmentNormal = normal;
	fragmentColor = color;
}
)";

// Lambert shading of the triangles (a quarter ambient, so that faces turned away from the light
// keep their colour); lines and points carry no normal and keep theirs.
const char* kFragmentShader = R"(#version 330
uniform vec3 light;
in vec3 fragmentNormal;
in vec4 fragmentColor;
out vec4 outColor;
void main()
{
	float n = length(fragmentNormal);
	if (n < 0.5)
	{
		outColor = fragmentColor;
		return;
	}
	float diffuse = max(dot(fragmentNormal / n, light), 0.0);
	outColor = vec4(fragmentColor.rgb * (0.25 + 0.75 * diffuse), fragmentColor.a);
}
)";
} // namespace

GlMeshRenderer::GlMeshRenderer()
{
	m_program = CompileProgram(kVertexShader, kFragmentShader);
	m_viewProjection = glGetUniformLocation(m_program, "viewProjection");
	m_light = glGetUniformLocation(m_program, "light");
	glGenVertexArrays(1, &m_array);
	glGenBuffers(1, &m_buffer);
	glBindVertexArray(m_array);
	glBindBuffer(GL_ARRAY_BUFFER, m_buffer);
	for (GLuint i = 0; i < 4; ++i)
		glEnableVertexAttribArray(i);
	glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), (void*)offsetof(MeshVertex, x));
	glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), (void*)offsetof(MeshVertex, nx));
	glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), (void*)offsetof(MeshVertex, r));
	glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), (void*)offsetof(MeshVertex, size));
	glBindVertexArray(0);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
}

GlMeshRenderer::~GlMeshRenderer()
{
	glDeleteBuffers(1, &m_buffer);
	glDeleteVertexArrays(1, &m_array);
	glDeleteProgram(m_program);
}

void GlMeshRenderer::Stream(const std::vector<MeshVertex>& vertices, unsigned mode)
{
	if (vertices.empty())
		return;
	glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(MeshVertex)), vertices.data(), GL_STREAM_DRAW);
	glDrawArrays(mode, 0, GLsizei(vertices.size()));
}

void GlMeshRenderer::Draw(const MeshBatch& batch, const OrbitCamera& camera)
{
	if (batch.Triangles().empty() && batch.Lines().empty() && batch.OverlayLines().empty() && batch.Points().empty())
		return;
	float vp[16];
	camera.ViewProjection(vp);
	const Vec3 l = camera.LightDirection();
	glUseProgram(m_program);
	glUniformMatrix4fv(m_viewProjection, 1, GL_FALSE, vp);
	glUniform3f(m_light, float(l.x), float(l.y), float(l.z));
	glBindVertexArray(m_array);
	glBindBuffer(GL_ARRAY_BUFFER, m_buffer);
	glClear(GL_DEPTH_BUFFER_BIT);
	glEnable(GL_DEPTH_TEST);
	glDepthFunc(GL_LESS);
	Stream(batch.Triangles(), GL_TRIANGLES);
	Stream(batch.Lines(), GL_LINES);
	glDisable(GL_DEPTH_TEST);
	Stream(batch.OverlayLines(), GL_LINES);
	glEnable(GL_PROGRAM_POINT_SIZE);
	Stream(batch.Points(), GL_POINTS);
	glDisable(GL_PROGRAM_POINT_SIZE);
	glBindVertexArray(0);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	glUseProgram(0);
}

} // namespace b2a::viewer
