// b2analytic: what the b2a_contact request handlers share: request errors naming the field,
// numbers and 2- or 3-vectors read from a request, the allowed fields of an object.
#pragma once

#include "b2analytic/3d/Math3.h"
#include "b2analytic/ContactResult.h"
#include "b2analytic/TimeOfImpact.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace b2a::tool
{

/// JSON with fields kept in the order written ("id" and "status" first in the answers).
using json = nlohmann::ordered_json;

/// A request error: the message names the field.
struct RequestError : std::runtime_error
{
	using std::runtime_error::runtime_error;
};

/// The finite number obj[key] (path: the field's prefix in messages), or `fallback` when it is
/// missing and not required.
inline double Number(const json& obj, const std::string& key, const std::string& path, bool required, double fallback)
{
	const auto it = obj.find(key);
	if (it == obj.end())
	{
		if (required)
			throw RequestError("field '" + path + key + "' is missing");
		return fallback;
	}
	if (!it->is_number())
		throw RequestError("field '" + path + key + "' must be a number, got " + it->dump());
	const double v = it->get<double>();
	if (!std::isfinite(v))
		throw RequestError("field '" + path + key + "' must be finite, got " + it->dump());
	return v;
}

/// The array of `size` finite numbers obj[key], or `fallback` when it is missing and not required.
inline std::vector<double> Numbers(const json& obj, const std::string& key, const std::string& path, size_t size, bool required,
                                   const std::vector<double>& fallback)
{
	const auto it = obj.find(key);
	if (it == obj.end())
	{
		if (required)
			throw RequestError("field '" + path + key + "' is missing");
		return fallback;
	}
	const std::string what = "field '" + path + key + "' must be an array of " + std::to_string(size) + " finite numbers, got ";
	if (!it->is_array() || it->size() != size)
		throw RequestError(what + it->dump());
	std::vector<double> out;
	for (const auto& v : *it)
	{
		if (!v.is_number() || !std::isfinite(v.get<double>()))
			throw RequestError(what + it->dump());
		out.push_back(v.get<double>());
	}
	return out;
}

/// Throws naming the first field of obj that is not in `allowed` (what: "a circle", ...).
inline void CheckKeys(const json& obj, const std::set<std::string>& allowed, const std::string& path, const std::string& what)
{
	for (auto it = obj.begin(); it != obj.end(); ++it)
		if (!allowed.count(it.key()))
		{
			std::string list;
			for (const auto& k : allowed)
				list += (list.empty() ? "" : ", ") + k;
			throw RequestError("field '" + path + it.key() + "' is not a field of " + what + " (expected " + list + ")");
		}
}

/// The request's shape `key` must be an object with a string "type": returns the type.
inline std::string ShapeType(const json& request, const std::string& key)
{
	const auto it = request.find(key);
	if (it == request.end())
		throw RequestError("field '" + key + "' is missing");
	if (!it->is_object())
		throw RequestError("field '" + key + "' must be a shape object, got " + it->dump());
	const auto type = it->find("type");
	if (type == it->end())
		throw RequestError("field '" + key + ".type' is missing");
	if (!type->is_string())
		throw RequestError("field '" + key + ".type' must be a string, got " + type->dump());
	return type->get<std::string>();
}

/// A 2-vector as a JSON array.
inline json ToJson(Vec2 v) { return json::array({v.x, v.y}); }
/// A 3-vector as a JSON array.
inline json ToJson(Vec3 v) { return json::array({v.x, v.y, v.z}); }

/// A contact's fields in an answer (ContactResult or ContactResult3): method, convergence,
/// scale, point, normal, point_a, point_b, separation, touching, iterations.
template <class Contact>
void WriteContact(json& out, const Contact& c)
{
	out["method"] = MethodName(c.method);
	out["convergence"] = StatusName(c.status);
	out["scale"] = c.level;
	out["point"] = ToJson(c.point);
	out["normal"] = ToJson(c.normal);
	out["point_a"] = ToJson(c.pointA);
	out["point_b"] = ToJson(c.pointB);
	out["separation"] = c.separation;
	out["touching"] = c.touching;
	out["iterations"] = c.iterations;
}

/// The tool's cap on conservative-advancement steps in mode toi. The library's default
/// (TimeOfImpactOptions::maxIterations) suits a caller that chose its horizon; a request line can
/// ask for any t_max, and a fast spin over a long horizon takes steps of gap / (|ω|·R) each, so
/// one line could keep the tool busy for minutes. Past the cap the line gets an error naming it.
constexpr int kToolTimeOfImpactSteps = 200;

/// The time-of-impact options the tool uses in both dimensions.
inline TimeOfImpactOptions ToolTimeOfImpactOptions()
{
	TimeOfImpactOptions options;
	options.maxIterations = kToolTimeOfImpactSteps;
	return options;
}

/// The error for a failed time of impact: the step cap named with the request's t_max, any other
/// failure as the solver reported it.
inline RequestError TimeOfImpactError(const char* failure, int steps, const json& request)
{
	if (steps >= kToolTimeOfImpactSteps)
		return RequestError("time of impact failed: conservative advancement reached the tool's cap of " +
		                    std::to_string(kToolTimeOfImpactSteps) + " steps before field 't_max' = " + request["t_max"].dump() +
		                    " (a shorter t_max needs fewer steps)");
	return RequestError(std::string("time of impact failed: ") + failure);
}

/// A time-of-impact answer's fields: the contact's at the first contact, or, with none before
/// t_max, "time", "point" and "normal" null and the gap at t_max.
template <class TimeOfImpactResult>
void WriteTimeOfImpact(json& out, const TimeOfImpactResult& r)
{
	out["time"] = r.hit ? json(r.time) : json(nullptr);
	WriteContact(out, r.contact);
	if (!r.hit)
	{
		out["point"] = nullptr;
		out["normal"] = nullptr;
		out["separation_at_t_max"] = r.contact.separation;
		out.erase("point_a");
		out.erase("point_b");
		out.erase("separation");
		out.erase("touching");
	}
	out["iterations"] = r.iterations;
}

/// True for the 3D shape types (sphere, ellipsoid, superellipsoid).
inline bool Is3dType(const std::string& type) { return type == "sphere" || type == "ellipsoid" || type == "superellipsoid"; }

/// The answer to a request with 3D shapes (modes common, scale_a, contact, toi), ContactTool3.cpp.
json Answer3(const json& request, const std::string& mode, const std::string& method);

/// The --help text's part on 3D shapes and the toi mode.
const char* ContactTool3Help();

} // namespace b2a::tool
