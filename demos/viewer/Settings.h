// b2a_viewer: the settings the panel changes, kept between runs in a JSON file.
#pragma once

#include <map>
#include <string>

namespace b2a::viewer
{

/// How a sample's world is stepped. Each sample has its own defaults (Sample::Defaults): the
/// millimetre scenes keep the demos' small steps, the metre scenes Box2D's testbed values.
struct StepSettings
{
	double hertz = 60.0;        ///< steps per simulated second (time step 1/hertz)
	int velocityIterations = 8; ///< Box2D velocity iterations
	int positionIterations = 3; ///< Box2D position iterations
	int stepsPerFrame = 1;      ///< world steps per drawn frame (the millimetre scenes take several)
	bool sleep = true;          ///< let resting bodies sleep
	bool warmStarting = true;   ///< Box2D's warm starting of the contact impulses
	bool continuous = true;     ///< time of impact (Box2D's continuous collision)
};

/// What the panel draws (Box2D's b2Draw flags and this viewer's own).
struct DrawSettings
{
	bool shapes = true;          ///< fixtures (analytic ones as their true outlines)
	bool joints = true;          ///< joints
	bool aabbs = false;          ///< fixtures' bounding boxes
	bool contactPoints = false;  ///< manifold points of touching contacts
	bool contactNormals = false; ///< their normals
	bool contactImpulses = false; ///< their normal impulses, as lines along the normal
	bool centresOfMass = false;  ///< bodies' centres of mass (b2Draw's transform axes)
	bool statistics = true;      ///< body, contact and frame-time counts in the panel
	bool profile = false;        ///< Box2D's step profile in the panel
};

/// How the scene is compared with Box2D's own polygons.
enum class CompareMode : int
{
	analytic = 0, ///< analytic particles only
	polygons,     ///< the same scene with every analytic particle switched to a Box2D 8-gon
	sideBySide    ///< both, analytic on the left, 8-gons on the right, stepped together
};

/// Everything kept between runs.
struct Settings
{
	std::string sample;            ///< key of the sample shown (SampleKey), empty: the first
	int windowWidth = 1280;        ///< window size in screen pixels
	int windowHeight = 800;        ///< window size in screen pixels
	bool showPanel = true;         ///< the panel (Tab toggles it)
	bool pause = false;            ///< stepping stopped (P)
	CompareMode compare = CompareMode::analytic; ///< analytic, 8-gons or both
	bool countMethods = true;      ///< count contacts by method (re-solving them every few frames)
	DrawSettings draw;             ///< what is drawn
	std::map<std::string, StepSettings> steps; ///< per sample key, once the user has visited it
};

/// Read settings from a JSON file. Returns "" on success (a missing file leaves the defaults and
/// succeeds); otherwise a message naming the file, the field and the value, and `settings` is
/// left as it was.
std::string LoadSettings(const std::string& path, Settings& settings);

/// Write settings as JSON (creating the folder). Returns "" or a message naming the file.
std::string SaveSettings(const std::string& path, const Settings& settings);

/// The default settings file: $XDG_CONFIG_HOME/b2a_viewer/settings.json, else
/// $HOME/.config/b2a_viewer/settings.json, else b2a_viewer_settings.json in the working folder.
std::string DefaultSettingsPath();

/// A message naming the field and value when a step setting is out of range, else "".
std::string CheckStepSettings(const StepSettings& s);

} // namespace b2a::viewer
