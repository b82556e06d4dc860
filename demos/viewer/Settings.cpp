// b2a_viewer: settings kept between runs (JSON through nlohmann_json).
#include "Settings.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace b2a::viewer
{
namespace
{
using Json = nlohmann::json;

// Range checks name the field and the value, as the project's bad-input rule asks.
std::string Range(const std::string& field, double value, double lo, double hi)
{
	if (std::isfinite(value) && value >= lo && value <= hi)
		return "";
	std::ostringstream s;
	s << "field '" << field << "' must be in [" << lo << ", " << hi << "], got " << value;
	return s.str();
}

// Reads `field` of `j` into `value` when present; a value of the wrong type is an error.
template <typename T>
std::string Read(const Json& j, const std::string& field, T& value)
{
	if (!j.contains(field))
		return "";
	try
	{
		value = j.at(field).get<T>();
	}
	catch (const Json::exception&)
	{
		return "field '" + field + "' has the wrong type, got " + j.at(field).dump();
	}
	return "";
}

Json ToJson(const StepSettings& s)
{
	return {{"hertz", s.hertz},
	        {"velocityIterations", s.velocityIterations},
	        {"positionIterations", s.positionIterations},
	        {"stepsPerFrame", s.stepsPerFrame},
	        {"sleep", s.sleep},
	        {"warmStarting", s.warmStarting},
	        {"continuous", s.continuous}};
}

std::string FromJson(const Json& j, const std::string& prefix, StepSettings& s)
{
	std::string e;
	for (auto r : {Read(j, "hertz", s.hertz), Read(j, "velocityIterations", s.velocityIterations),
	               Read(j, "positionIterations", s.positionIterations), Read(j, "stepsPerFrame", s.stepsPerFrame),
	               Read(j, "sleep", s.sleep), Read(j, "warmStarting", s.warmStarting), Read(j, "continuous", s.continuous)})
		if (e.empty() && !r.empty())
			e = r;
	if (e.empty())
		e = CheckStepSettings(s);
	return e.empty() ? "" : prefix + e;
}

Json ToJson(const DrawSettings& d)
{
	return {{"shapes", d.shapes},
	        {"joints", d.joints},
	        {"aabbs", d.aabbs},
	        {"contactPoints", d.contactPoints},
	        {"contactNormals", d.contactNormals},
	        {"contactImpulses", d.contactImpulses},
	        {"centresOfMass", d.centresOfMass},
	        {"statistics", d.statistics},
	        {"profile", d.profile}};
}

std::string FromJson(const Json& j, DrawSettings& d)
{
	for (auto r : {Read(j, "shapes", d.shapes), Read(j, "joints", d.joints), Read(j, "aabbs", d.aabbs),
	               Read(j, "contactPoints", d.contactPoints), Read(j, "contactNormals", d.contactNormals),
	               Read(j, "contactImpulses", d.contactImpulses), Read(j, "centresOfMass", d.centresOfMass),
	               Read(j, "statistics", d.statistics), Read(j, "profile", d.profile)})
		if (!r.empty())
			return "draw: " + r;
	return "";
}

std::string Parse(const Json& j, Settings& s)
{
	if (!j.is_object())
		return "the file is not a JSON object";
	int compare = int(s.compare);
	for (auto r : {Read(j, "sample", s.sample), Read(j, "windowWidth", s.windowWidth), Read(j, "windowHeight", s.windowHeight),
	               Read(j, "showPanel", s.showPanel), Read(j, "pause", s.pause), Read(j, "compare", compare),
	               Read(j, "countMethods", s.countMethods)})
		if (!r.empty())
			return r;
	for (auto r : {Range("windowWidth", s.windowWidth, 200, 16384), Range("windowHeight", s.windowHeight, 200, 16384),
	               Range("compare", compare, 0, 2)})
		if (!r.empty())
			return r;
	s.compare = CompareMode(compare);
	if (j.contains("draw"))
		if (std::string e = FromJson(j.at("draw"), s.draw); !e.empty())
			return e;
	if (j.contains("steps"))
	{
		if (!j.at("steps").is_object())
			return "field 'steps' must be an object of sample keys, got " + j.at("steps").dump();
		for (auto& [key, value] : j.at("steps").items())
		{
			StepSettings step;
			if (std::string e = FromJson(value, "steps." + key + ": ", step); !e.empty())
				return e;
			s.steps[key] = step;
		}
	}
	return "";
}
} // namespace

std::string CheckStepSettings(const StepSettings& s)
{
	for (auto r : {Range("hertz", s.hertz, 1.0, 1e6), Range("velocityIterations", s.velocityIterations, 1, 500),
	               Range("positionIterations", s.positionIterations, 0, 500), Range("stepsPerFrame", s.stepsPerFrame, 1, 1000)})
		if (!r.empty())
			return r;
	return "";
}

std::string LoadSettings(const std::string& path, Settings& settings)
{
	std::ifstream in(path);
	if (!in)
		return std::filesystem::exists(path) ? "settings file '" + path + "' cannot be read" : "";
	Json j;
	try
	{
		in >> j;
	}
	catch (const Json::exception& e)
	{
		return "settings file '" + path + "' is not valid JSON: " + e.what();
	}
	Settings s = settings;
	if (std::string e = Parse(j, s); !e.empty())
		return "settings file '" + path + "': " + e;
	settings = s;
	return "";
}

std::string SaveSettings(const std::string& path, const Settings& s)
{
	Json steps = Json::object();
	for (const auto& [key, step] : s.steps)
		steps[key] = ToJson(step);
	const Json j = {{"sample", s.sample},
	                {"windowWidth", s.windowWidth},
	                {"windowHeight", s.windowHeight},
	                {"showPanel", s.showPanel},
	                {"pause", s.pause},
	                {"compare", int(s.compare)},
	                {"countMethods", s.countMethods},
	                {"draw", ToJson(s.draw)},
	                {"steps", steps}};
	std::error_code ec;
	const std::filesystem::path parent = std::filesystem::path(path).parent_path();
	if (!parent.empty())
		std::filesystem::create_directories(parent, ec);
	std::ofstream out(path);
	out << j.dump(1, '\t') << "\n";
	return out ? "" : "settings file '" + path + "' cannot be written";
}

std::string DefaultSettingsPath()
{
	if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
		return std::string(xdg) + "/b2a_viewer/settings.json";
	if (const char* home = std::getenv("HOME"); home && *home)
		return std::string(home) + "/.config/b2a_viewer/settings.json";
	return "b2a_viewer_settings.json";
}

} // namespace b2a::viewer
