// b2a_viewer: OpenGL drawing of the debug batch, and screenshots.
#include "GlRenderer.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <stb_image_write.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace b2a::viewer
{
namespace
{
const char* kVertexShader = R"(#version 330
uniform mat4 projection;
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 color;
layout(location = 2) in float size;
out vec4 fragmentColor;
void main()
{
	gl_Position = projection * vec4(position, 0.0, 1.0);
	gl_PointSize = size;
	fragmentColor = color;
}
)";

const char* kFragmentShader = R"(#version 330
in vec4 fragmentColor;
out vec4 outColor;
void main()
{
	outColor = fragmentColor;
}
)";

GLuint Compile(GLenum type, const char* source)
{
	const GLuint shader = glCreateShader(type);
	glShaderSource(shader, 1, &source, nullptr);
	glCompileShader(shader);
	GLint ok = 0;
	glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
	if (!ok)
	{
		char log[1024] = {};
		glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
		glDeleteShader(shader);
		throw std::runtime_error(std::string("b2a_viewer: OpenGL shader does not compile: ") + log);
	}
	return shader;
}
} // namespace

unsigned CompileProgram(const char* vertexShader, const char* fragmentShader)
{
	const GLuint vs = Compile(GL_VERTEX_SHADER, vertexShader), fs = Compile(GL_FRAGMENT_SHADER, fragmentShader);
	const GLuint program = glCreateProgram();
	glAttachShader(program, vs);
	glAttachShader(program, fs);
	glLinkProgram(program);
	glDeleteShader(vs);
	glDeleteShader(fs);
	GLint ok = 0;
	glGetProgramiv(program, GL_LINK_STATUS, &ok);
	if (!ok)
	{
		char log[1024] = {};
		glGetProgramInfoLog(program, sizeof(log), nullptr, log);
		glDeleteProgram(program);
		throw std::runtime_error(std::string("b2a_viewer: OpenGL program does not link: ") + log);
	}
	return program;
}

GlRenderer::GlRenderer()
{
	m_program = CompileProgram(kVertexShader, kFragmentShader);
	m_projection = glGetUniformLocation(m_program, "projection");
	glGenVertexArrays(3, m_arrays);
	glGenBuffers(3, m_buffers);
	for (int i = 0; i < 3; ++i)
	{
		glBindVertexArray(m_arrays[i]);
		glBindBuffer(GL_ARRAY_BUFFER, m_buffers[i]);
		glEnableVertexAttribArray(0);
		glEnableVertexAttribArray(1);
		glEnableVertexAttribArray(2);
		glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(DrawVertex), (void*)offsetof(DrawVertex, x));
		glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(DrawVertex), (void*)offsetof(DrawVertex, r));
		glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(DrawVertex), (void*)offsetof(DrawVertex, size));
	}
	glBindVertexArray(0);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
}

GlRenderer::~GlRenderer()
{
	glDeleteBuffers(3, m_buffers);
	glDeleteVertexArrays(3, m_arrays);
	glDeleteProgram(m_program);
}

void GlRenderer::Stream(int list, const std::vector<DrawVertex>& vertices, unsigned mode)
{
	if (vertices.empty())
		return;
	glBindVertexArray(m_arrays[list]);
	glBindBuffer(GL_ARRAY_BUFFER, m_buffers[list]);
	glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(DrawVertex)), vertices.data(), GL_STREAM_DRAW);
	glDrawArrays(mode, 0, GLsizei(vertices.size()));
}

void GlRenderer::Draw(const DrawBatch& batch, const Camera& camera)
{
	float projection[16];
	camera.Projection(projection);
	glUseProgram(m_program);
	glUniformMatrix4fv(m_projection, 1, GL_FALSE, projection);
	glEnable(GL_BLEND);
	glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
	glEnable(GL_PROGRAM_POINT_SIZE);
	Stream(0, batch.Triangles(), GL_TRIANGLES);
	Stream(1, batch.Lines(), GL_LINES);
	Stream(2, batch.Points(), GL_POINTS);
	glDisable(GL_PROGRAM_POINT_SIZE);
	glDisable(GL_BLEND);
	glBindVertexArray(0);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	glUseProgram(0);
}

std::string WriteScreenshot(const std::string& path, int width, int height)
{
	// OpenGL's rows run bottom to top; stb writes the first row at the top.
	std::vector<unsigned char> rgb(size_t(width) * size_t(height) * 3);
	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	glReadBuffer(GL_BACK);
	glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
	stbi_flip_vertically_on_write(1);
	const int ok = stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3);
	stbi_flip_vertically_on_write(0);
	return ok ? "" : "b2a_viewer: cannot write the screenshot '" + path + "'";
}

} // namespace b2a::viewer
