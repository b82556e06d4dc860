// b2analytic: b2a_contact requests: parse a line, solve, format the answer.
#include "ContactTool.h"

#include "b2analytic/b2analytic.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>

namespace b2a::tool
{

namespace
{
using json = nlohmann::ordered_json; // keeps "id" and "status" first in the answers

// A request error: the message names the field.
struct RequestError : std::runtime_error
{
	using std::runtime_error::runtime_error;
};

double Number(const json& obj, const std::string& key, const std::string& path, bool required, double fallback)
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

void CheckKeys(const json& obj, const std::set<std::string>& allowed, const std::string& path, const std::string& what)
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

struct ParsedShape
{
	std::shared_ptr<const Shape> shape;
	Pose pose;
};

ParsedShape ParseShape(const json& request, const std::string& key)
{
	const auto it = request.find(key);
	if (it == request.end())
		throw RequestError("field '" + key + "' is missing");
	const json& s = *it;
	const std::string path = key + ".";
	if (!s.is_object())
		throw RequestError("field '" + key + "' must be a shape object, got " + s.dump());
	const auto type = s.find("type");
	if (type == s.end())
		throw RequestError("field '" + path + "type' is missing");
	if (!type->is_string())
		throw RequestError("field '" + path + "type' must be a string, got " + type->dump());
	const std::string t = type->get<std::string>();
	ParsedShape out;
	try
	{
		if (t == "superellipse")
		{
			CheckKeys(s, {"type", "a", "b", "n", "m", "x", "y", "angle"}, path, "a superellipse");
			out.shape = MakeSuperellipse(Number(s, "a", path, true, 0), Number(s, "b", path, true, 0),
			                             Number(s, "n", path, true, 0), Number(s, "m", path, true, 0));
		}
		else if (t == "ellipse")
		{
			CheckKeys(s, {"type", "a", "b", "x", "y", "angle"}, path, "an ellipse");
			out.shape = MakeEllipse(Number(s, "a", path, true, 0), Number(s, "b", path, true, 0));
		}
		else if (t == "circle")
		{
			CheckKeys(s, {"type", "r", "x", "y", "angle"}, path, "a circle");
			out.shape = MakeCircle(Number(s, "r", path, true, 0));
		}
		else if (t == "heart")
		{
			CheckKeys(s, {"type", "alpha", "x", "y", "angle"}, path, "a heart");
			out.shape = MakeHeart(Number(s, "alpha", path, true, 0));
		}
		else
		{
			throw RequestError("field '" + path + "type': unknown shape type \"" + t +
			                   "\" (expected superellipse, ellipse, circle or heart)");
		}
	}
	catch (const InvalidParameter& e)
	{
		// The shape's own message names its field; say which shape it was.
		throw RequestError("shape '" + key + "': " + e.what());
	}
	out.pose = Pose(Vec2(Number(s, "x", path, false, 0.0), Number(s, "y", path, false, 0.0)), Number(s, "angle", path, false, 0.0));
	return out;
}

bool SuperellipseFamily(const Shape& s)
{
	return dynamic_cast<const SuperellipseShape*>(&s) != nullptr;
}

// The shape's type as the request names it ("heart"): its description up to the parameters.
std::string TypeName(const Shape& s)
{
	const std::string d = s.Describe();
	return d.substr(0, d.find('('));
}

json Vec(Vec2 v)
{
	return json::array({v.x, v.y});
}

json Answer(const json& request, json& id)
{
	if (!request.is_object())
		throw RequestError("a request must be a JSON object, got " + request.dump());
	if (request.contains("id"))
		id = request["id"];
	CheckKeys(request, {"id", "mode", "method", "a", "b"}, "", "a request");
	std::string mode = "contact", method = "auto";
	if (request.contains("mode"))
	{
		if (!request["mode"].is_string())
			throw RequestError("field 'mode' must be a string, got " + request["mode"].dump());
		mode = request["mode"].get<std::string>();
	}
	if (mode != "common" && mode != "scale_a" && mode != "contact")
		throw RequestError("field 'mode': unknown mode \"" + mode + "\" (expected common, scale_a or contact)");
	if (request.contains("method"))
	{
		if (!request["method"].is_string())
			throw RequestError("field 'method' must be a string, got " + request["method"].dump());
		method = request["method"].get<std::string>();
	}
	MethodChoice choice;
	if (method == "auto")
		choice = MethodChoice::automatic;
	else if (method == "newton")
		choice = MethodChoice::newton;
	else if (method == "grid")
		choice = MethodChoice::grid;
	else
		throw RequestError("field 'method': unknown method \"" + method + "\" (expected auto, newton or grid)");

	const ParsedShape a = ParseShape(request, "a");
	const ParsedShape b = ParseShape(request, "b");
	const Shape& sa = *a.shape;
	const Shape& sb = *b.shape;

	ContactResult c;
	if (mode == "contact")
	{
		c = ComputeContact(sa, a.pose, sb, b.pose, choice);
	}
	else
	{
		LevelResult level;
		bool touching = false;
		if (mode == "common")
		{
			if (!SuperellipseFamily(sa) || !SuperellipseFamily(sb))
				throw RequestError("mode 'common' is defined for the superellipse family only (superellipse, ellipse, "
				                   "circle); use mode 'scale_a' for " + TypeName(SuperellipseFamily(sa) ? sb : sa) + " shapes");
			level = SolveCommonLevel(sa, a.pose, sb, b.pose, choice);
			touching = level.level <= 1.0;
		}
		else
		{
			level = SolveScaleA(sa, a.pose, sb, b.pose, choice);
			touching = level.level <= sa.SurfaceLevel();
		}
		if (!level.Ok())
			throw RequestError(std::string("solver failed (") + MethodName(level.method) + "): " + level.failure);
		c = ContactFromLevel(sa, a.pose, sb, b.pose, level, touching, mode == "scale_a");
		c.normal = level.normal; // these modes report ∇λA's direction at the point
	}
	if (!c.Ok())
		throw RequestError(std::string("solver failed (") + MethodName(c.method) + "): " + c.failure);
	if (!std::isfinite(c.level) || !IsFinite(c.point) || !IsFinite(c.normal) || !std::isfinite(c.separation))
		throw RequestError("solver returned a non-finite value");
	json out;
	out["id"] = id;
	out["status"] = "ok";
	out["mode"] = mode;
	out["method"] = MethodName(c.method);
	out["convergence"] = StatusName(c.status);
	out["scale"] = c.level;
	out["point"] = Vec(c.point);
	out["normal"] = Vec(c.normal);
	out["point_a"] = Vec(c.pointA);
	out["point_b"] = Vec(c.pointB);
	out["separation"] = c.separation;
	out["touching"] = c.touching;
	out["iterations"] = c.iterations;
	return out;
}
} // namespace

std::string AnswerContactRequest(const std::string& line, bool& ok)
{
	json id = nullptr;
	ok = false;
	auto error = [&](const std::string& message) {
		const json err = {{"id", id}, {"status", "error"}, {"error", message}};
		return err.dump(-1, ' ', false, json::error_handler_t::replace);
	};
	json request;
	try
	{
		request = json::parse(line);
	}
	catch (const json::exception& e)
	{
		return error(std::string("malformed JSON: ") + e.what()); // syntax errors, number overflow
	}
	try
	{
		const json out = Answer(request, id);
		ok = true;
		return out.dump(-1, ' ', false, json::error_handler_t::replace);
	}
	catch (const std::exception& e)
	{
		return error(e.what());
	}
}

const char* ContactToolHelp()
{
	return R"(b2a_contact: contact detection between analytic particles, JSON Lines in, JSON Lines out.

Usage: b2a_contact [FILE]       (reads standard input without FILE or with FILE = -)
       b2a_contact --help

Each input line is one JSON object (blank lines are skipped):
  {"id": <any JSON value>, "mode": "common" | "scale_a" | "contact",
   "method": "auto" | "newton" | "grid", "a": <shape>, "b": <shape>}
mode defaults to "contact", method to "auto". A shape is one of
  {"type": "superellipse", "a": A, "b": B, "n": N, "m": M, "x": X, "y": Y, "angle": T}
  {"type": "ellipse", "a": A, "b": B, "x": X, "y": Y, "angle": T}
  {"type": "circle", "r": R, "x": X, "y": Y}
  {"type": "heart", "alpha": AL, "x": X, "y": Y, "angle": T}
x, y and angle default to 0; the angle is in radians and rotates body to world counter-clockwise.
Superellipse: |x/a|^n + |y/b|^m <= 1 (n, m >= 1, any real); heart: (x^2+y^2-alpha)^3 - x^2 y^3 <= 0.

Each line gets one answer, in order:
  {"id": ..., "status": "ok", "mode": ..., "method": "<solver used>",
   "convergence": "converged" | "converged_after_fallback", "scale": C,
   "point": [X, Y], "normal": [NX, NY], "point_a": [..], "point_b": [..],
   "separation": S, "touching": true|false, "iterations": K}
or {"id": ..., "status": "error", "error": "<message naming the field>"}; the next line is
then answered as usual.

Modes:
  common   scale is the common level C at which the two particles' level sets touch
           (C > 1 apart, C = 1 tangent, C < 1 overlapping); point is the touching point;
           normal is the direction of grad F_A there. Superellipse family only.
           Methods: newton (Newton-Raphson alone), grid (fixed point of the grid method),
           auto (closed form for circles, else Newton with the min-max fallback).
  scale_a  B is held at its own surface; scale is the smallest level of A (superellipse: f,
           heart: alpha) at which A touches B; point is where, on B's surface.
           Methods: grid (auto), newton (smooth convex shapes only).
  contact  the contact a physics engine uses: normal from A to B, point_a and point_b on the
           unscaled surfaces on the line through point along the normal, separation along
           the normal (negative when overlapping), scale the level value of the method used.
           Methods: auto (per shape pair), newton, grid (one side, or both: see ChooseGridSide).
method in the answer: closed_form, ellipse_pair (two ellipses), newton, min_max, grid or overlap_axis
(coincident centres).

Exit status: 0 when every line was answered "ok", 1 when some line got an error,
2 when the input cannot be read or the arguments are wrong.

Example:
  echo '{"id":1,"a":{"type":"circle","r":1},"b":{"type":"circle","r":1,"x":3}}' | b2a_contact
)";
}

} // namespace b2a::tool
