// b2a_viewer: an interactive viewer in the style of Box2D's testbed (GLFW, OpenGL 3.3, Dear
// ImGui). With --frames it runs that many frames and exits, writing a screenshot and a report
// on request: the headless tests run it so under Xvfb.
#include "GlMeshRenderer.h"
#include "GlRenderer.h"
#include "SampleRegistry.h"
#include "Viewer.h"

#include <CLI/CLI.hpp>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

using namespace b2a::viewer;

namespace
{
Viewer* FromWindow(GLFWwindow* w)
{
	return static_cast<Viewer*>(glfwGetWindowUserPointer(w));
}

// The callbacks hand each event to Dear ImGui first and to the viewer unless the panel takes it;
// button releases always reach the viewer, so that a drag ending over the panel still ends.
void KeyCallback(GLFWwindow* w, int key, int scancode, int action, int mods)
{
	ImGui_ImplGlfw_KeyCallback(w, key, scancode, action, mods);
	if (!ImGui::GetIO().WantCaptureKeyboard)
		FromWindow(w)->OnKey(key, action, mods);
}

void MouseButtonCallback(GLFWwindow* w, int button, int action, int mods)
{
	ImGui_ImplGlfw_MouseButtonCallback(w, button, action, mods);
	if (!ImGui::GetIO().WantCaptureMouse || action == GLFW_RELEASE)
		FromWindow(w)->OnMouseButton(button, action, mods);
}

void CursorCallback(GLFWwindow* w, double x, double y)
{
	FromWindow(w)->OnCursor(b2Vec2(float(x), float(y)));
}

void ScrollCallback(GLFWwindow* w, double dx, double dy)
{
	ImGui_ImplGlfw_ScrollCallback(w, dx, dy);
	if (!ImGui::GetIO().WantCaptureMouse)
		FromWindow(w)->OnScroll(dy);
}

void ResizeCallback(GLFWwindow* w, int width, int height)
{
	FromWindow(w)->SetWindowSize(width, height);
}

void ErrorCallback(int code, const char* message)
{
	std::fprintf(stderr, "b2a_viewer: GLFW error %d: %s\n", code, message);
}

struct Options
{
	std::string sample;
	int frames = 0;
	std::string screenshot;
	std::string report;
	std::string settings = DefaultSettingsPath();
	std::string compare;
	int width = 0, height = 0;
};

// What the headless tests check: frame times, the world's soundness, where the bodies are on
// the screen and where the panel is.
void WriteReport(const std::string& path, Viewer& viewer)
{
	const FrameTimes& t = viewer.Times();
	const WorldHealth h = viewer.Health();
	nlohmann::ordered_json j;
	j["sample"] = SampleKey(Samples()[size_t(viewer.SampleIndex())]);
	j["frames"] = t.frames;
	j["steps"] = viewer.Current().StepCount();
	j["time_s"] = viewer.Current().Time();
	j["mean_frame_ms"] = t.frames > 0 ? t.totalFrame / t.frames : 0.0;
	j["mean_step_ms"] = t.frames > 0 ? t.totalStep / t.frames : 0.0;
	j["mean_draw_ms"] = t.frames > 0 ? t.totalDraw / t.frames : 0.0;
	j["mean_render_ms"] = t.frames > 0 ? t.totalRender / t.frames : 0.0;
	j["worst_frame_ms"] = t.worstFrame;
	j["bodies"] = h.bodies;
	j["non_finite"] = h.nonFinite;
	j["escaped"] = h.escaped;
	j["window"] = {viewer.View().width, viewer.View().height};
	j["background"] = {Viewer::kBackground[0], Viewer::kBackground[1], Viewer::kBackground[2]};
	const float* r = viewer.PanelRect();
	j["panel"] = {r[0], r[1], r[2], r[3]};
	nlohmann::ordered_json points = nlohmann::ordered_json::array();
	for (b2Vec2 p : viewer.BodyScreenPoints())
		points.push_back({p.x, p.y});
	j["body_screen_points"] = points;
	viewer.CountMethodsNow();
	nlohmann::ordered_json methods = nlohmann::ordered_json::object();
	for (const auto& [name, tally] : viewer.Methods().methods)
		methods[name] = {{"contacts", tally.contacts}, {"touching", tally.touching}, {"mean_us", tally.Mean()}};
	j["methods"] = methods;
	j["readings"] = viewer.Current().Readings();
	const char* compare[] = {"analytic", "polygons", "side-by-side"};
	j["compare"] = compare[int(viewer.GetSettings().compare)];
	std::ofstream out(path);
	out << j.dump(1, '\t') << "\n";
	if (!out)
		throw std::runtime_error("b2a_viewer: cannot write the report '" + path + "'");
}

int Run(const Options& o, Settings& settings)
{
	glfwSetErrorCallback(ErrorCallback);
	if (!glfwInit())
	{
		std::fprintf(stderr, "b2a_viewer: GLFW cannot start (no display? run it under xvfb-run for a headless run)\n");
		return 1;
	}
	glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
	glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
	glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
	glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
	GLFWwindow* window = glfwCreateWindow(settings.windowWidth, settings.windowHeight, "b2a_viewer", nullptr, nullptr);
	if (!window)
	{
		std::fprintf(stderr, "b2a_viewer: no OpenGL 3.3 window (see the GLFW error above)\n");
		glfwTerminate();
		return 1;
	}
	glfwMakeContextCurrent(window);
	glfwSwapInterval(o.frames > 0 ? 0 : 1); // headless runs go as fast as they can

	IMGUI_CHECKVERSION();
	ImGui::CreateContext();
	ImGui::GetIO().IniFilename = nullptr; // the viewer keeps its own settings
	ImGui::StyleColorsDark();
	ImGui_ImplGlfw_InitForOpenGL(window, false);
	ImGui_ImplOpenGL3_Init("#version 330");

	int status = 0;
	{
		if (!o.sample.empty())
			settings.sample = o.sample;
		Viewer viewer(settings);
		if (o.compare == "polygons")
			viewer.SetCompare(CompareMode::polygons);
		else if (o.compare == "side-by-side")
			viewer.SetCompare(CompareMode::sideBySide);
		else if (o.compare == "analytic")
			viewer.SetCompare(CompareMode::analytic);
		int fbw = 0, fbh = 0;
		glfwGetFramebufferSize(window, &fbw, &fbh);
		viewer.SetWindowSize(fbw, fbh);
		viewer.ResetView();
		glfwSetWindowUserPointer(window, &viewer);
		glfwSetKeyCallback(window, KeyCallback);
		glfwSetCharCallback(window, ImGui_ImplGlfw_CharCallback);
		glfwSetMouseButtonCallback(window, MouseButtonCallback);
		glfwSetCursorPosCallback(window, CursorCallback);
		glfwSetScrollCallback(window, ScrollCallback);
		glfwSetFramebufferSizeCallback(window, ResizeCallback);

		GlRenderer renderer;
		GlMeshRenderer meshRenderer;
		for (int frame = 1; !glfwWindowShouldClose(window) && !viewer.QuitRequested(); ++frame)
		{
			const auto t0 = std::chrono::steady_clock::now();
			glfwPollEvents();
			ImGui_ImplOpenGL3_NewFrame();
			ImGui_ImplGlfw_NewFrame();
			ImGui::NewFrame();
			viewer.Update();
			viewer.DrawScene();
			viewer.Panel();
			const auto r0 = std::chrono::steady_clock::now();
			ImGui::Render();
			glViewport(0, 0, viewer.View().width, viewer.View().height);
			glClearColor(Viewer::kBackground[0], Viewer::kBackground[1], Viewer::kBackground[2], 1.0f);
			glClear(GL_COLOR_BUFFER_BIT);
			renderer.Draw(viewer.Batch(), viewer.View());
			meshRenderer.Draw(viewer.Batch3(), viewer.Orbit());
			ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
			const bool last = o.frames > 0 && frame >= o.frames;
			if (last && !o.screenshot.empty())
				if (std::string e = WriteScreenshot(o.screenshot, viewer.View().width, viewer.View().height); !e.empty())
				{
					std::fprintf(stderr, "%s\n", e.c_str());
					status = 1;
				}
			glfwSwapBuffers(window);
			const auto t1 = std::chrono::steady_clock::now();
			viewer.RecordFrameTime(std::chrono::duration<double, std::milli>(t1 - t0).count(),
			                       std::chrono::duration<double, std::milli>(t1 - r0).count());
			if (o.frames > 0 && frame % 100 == 0)
				std::fprintf(stderr, "b2a_viewer: frame %d of %d, %.1f ms a frame\n", frame, o.frames, viewer.Times().meanFrame);
			if (last)
				break;
		}
		const FrameTimes& t = viewer.Times();
		const WorldHealth h = viewer.Health();
		if (!o.report.empty())
			WriteReport(o.report, viewer);
		const double n = t.frames > 0 ? double(t.frames) : 1.0;
		std::printf("b2a_viewer: %s: %d frames, mean frame %.2f ms (step %.2f ms, draw %.2f ms, render %.2f ms), worst %.1f ms; "
		            "%d bodies, %d non-finite, %d escaped\n",
		            settings.sample.c_str(), t.frames, t.totalFrame / n, t.totalStep / n, t.totalDraw / n, t.totalRender / n,
		            t.worstFrame, h.bodies, h.nonFinite, h.escaped);
		if (h.nonFinite > 0 || h.escaped > 0)
			status = 1;
	}
	ImGui_ImplOpenGL3_Shutdown();
	ImGui_ImplGlfw_Shutdown();
	ImGui::DestroyContext();
	glfwDestroyWindow(window);
	glfwTerminate();
	return status;
}
} // namespace

int main(int argc, char** argv)
{
	CLI::App app{"b2a_viewer: an interactive viewer of b2analytic's samples in the style of Box2D's testbed.\n"
	             "Keys: P pause, O single step, R restart, [ ] previous and next sample, Home reset view, arrows pan,\n"
	             "Z X or the wheel zoom, right drag pans, left drag moves a body, Shift and drag launches a bomb,\n"
	             "Tab hides the panel, Esc quits. In 3D samples left drag or the arrows turn the camera, Z X or the wheel\n"
	             "move it nearer and farther.",
	             "b2a_viewer"};
	Options o;
	std::vector<std::string> keys;
	for (const SampleEntry& e : Samples())
		keys.push_back(SampleKey(e));
	bool list = false;
	app.add_option("--sample", o.sample, "the sample to start with (--list shows them)")->check(CLI::IsMember(keys));
	app.add_option("--frames", o.frames, "run this many frames, then exit (headless runs)")->check(CLI::Range(1, 10000000));
	app.add_option("--screenshot", o.screenshot, "write the last frame as a PNG file (with --frames)");
	app.add_option("--report", o.report, "write frame times, body positions on screen and counts as JSON (with --frames)");
	app.add_option("--settings", o.settings, "settings file, kept between runs")->capture_default_str();
	app.add_option("--compare", o.compare, "analytic particles, Box2D 8-gons in their place, or both side by side")
		->check(CLI::IsMember({"analytic", "polygons", "side-by-side"}));
	app.add_option("--width", o.width, "window width in pixels")->check(CLI::Range(200, 16384));
	app.add_option("--height", o.height, "window height in pixels")->check(CLI::Range(200, 16384));
	app.add_flag("--list", list, "list the samples and exit");
	CLI11_PARSE(app, argc, argv);
	if ((!o.screenshot.empty() || !o.report.empty()) && o.frames == 0)
	{
		std::fprintf(stderr, "b2a_viewer: --screenshot and --report need --frames N (the frame they describe)\n");
		return 2;
	}
	if (list)
	{
		for (const SampleEntry& e : Samples())
			std::printf("%-24s %s / %s\n", SampleKey(e).c_str(), e.category, e.name);
		return 0;
	}

	Settings settings;
	if (std::string e = LoadSettings(o.settings, settings); !e.empty())
	{
		std::fprintf(stderr, "b2a_viewer: %s (fix or remove the file)\n", e.c_str());
		return 2;
	}
	if (o.width > 0)
		settings.windowWidth = o.width;
	if (o.height > 0)
		settings.windowHeight = o.height;
	int status = 0;
	try
	{
		status = Run(o, settings);
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "%s\n", e.what());
		return 1;
	}
	if (std::string e = SaveSettings(o.settings, settings); !e.empty())
		std::fprintf(stderr, "b2a_viewer: %s\n", e.c_str());
	return status;
}
