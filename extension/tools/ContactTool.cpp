// b2analytic: b2a_contact requests: parse a line, solve, format the answer.
#include "ContactTool.h"
#include "ContactToolCommon.h"

#include "b2analytic/b2analytic.h"

#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

namespace b2a::tool
{

namespace
{
struct ParsedShape
{
	std::shared_ptr<const Shape> shape;
	Pose pose;
	Vec2 velocity;              // toi only
	double angularVelocity = 0; // toi only
};

// A 2D shape; with `motion` (mode toi) it may carry "v" [vx, vy] and "w" (a number).
ParsedShape ParseShape(const json& request, const std::string& key, bool motion = false)
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
	auto keys = [motion](std::set<std::string> own) {
		if (motion)
			own.insert({"v", "w"});
		return own;
	};
	try
	{
		if (t == "superellipse")
		{
			CheckKeys(s, keys({"type", "a", "b", "n", "m", "x", "y", "angle"}), path, "a superellipse");
			out.shape = MakeSuperellipse(Number(s, "a", path, true, 0), Number(s, "b", path, true, 0),
			                             Number(s, "n", path, true, 0), Number(s, "m", path, true, 0));
		}
		else if (t == "ellipse")
		{
			CheckKeys(s, keys({"type", "a", "b", "x", "y", "angle"}), path, "an ellipse");
			out.shape = MakeEllipse(Number(s, "a", path, true, 0), Number(s, "b", path, true, 0));
		}
		else if (t == "circle")
		{
			CheckKeys(s, keys({"type", "r", "x", "y", "angle"}), path, "a circle");
			out.shape = MakeCircle(Number(s, "r", path, true, 0));
		}
		else if (t == "heart")
		{
			CheckKeys(s, keys({"type", "alpha", "x", "y", "angle"}), path, "a heart");
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
	const std::vector<double> v = Numbers(s, "v", path, 2, false, {0.0, 0.0});
	out.velocity = Vec2(v[0], v[1]);
	out.angularVelocity = Number(s, "w", path, false, 0.0);
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

// Mode toi in 2D: the first contact of two shapes moving with constant linear and angular
// velocities, or "time": null when none before t_max.
json AnswerTimeOfImpact(const json& request, const json& id)
{
	const ParsedShape a = ParseShape(request, "a", true), b = ParseShape(request, "b", true);
	const double tMax = Number(request, "t_max", "", true, 0.0);
	if (!(tMax >= 0.0))
		throw RequestError("field 't_max' must be >= 0, got " + request["t_max"].dump());
	const Motion ma{a.pose, a.velocity, a.angularVelocity}, mb{b.pose, b.velocity, b.angularVelocity};
	const TimeOfImpactResult r = TimeOfImpact(*a.shape, ma, *b.shape, mb, tMax, ToolTimeOfImpactOptions());
	if (!r.Ok())
		throw TimeOfImpactError(r.failure, r.iterations, request);
	const ContactResult& c = r.contact;
	if (!std::isfinite(r.time) || !std::isfinite(c.separation) || !IsFinite(c.point) || !IsFinite(c.normal) || !IsFinite(c.pointA) ||
	    !IsFinite(c.pointB))
		throw RequestError("solver returned a non-finite value");
	json out;
	out["id"] = id;
	out["status"] = "ok";
	out["mode"] = "toi";
	WriteTimeOfImpact(out, r);
	return out;
}

json Answer(const json& request, json& id)
{
	if (!request.is_object())
		throw RequestError("a request must be a JSON object, got " + request.dump());
	if (request.contains("id"))
		id = request["id"];
	CheckKeys(request, {"id", "mode", "method", "a", "b", "t_max"}, "", "a request");
	std::string mode = "contact", method = "auto";
	if (request.contains("mode"))
	{
		if (!request["mode"].is_string())
			throw RequestError("field 'mode' must be a string, got " + request["mode"].dump());
		mode = request["mode"].get<std::string>();
	}
	if (mode != "common" && mode != "scale_a" && mode != "contact" && mode != "toi")
		throw RequestError("field 'mode': unknown mode \"" + mode + "\" (expected common, scale_a, contact or toi)");
	if (request.contains("t_max") && mode != "toi")
		throw RequestError("field 't_max' belongs to mode 'toi' only (mode is '" + mode + "')");
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

	const bool a3 = Is3dType(ShapeType(request, "a")), b3 = Is3dType(ShapeType(request, "b"));
	if (a3 != b3)
		throw RequestError(std::string("field '") + (a3 ? "b" : "a") + ".type': shape '" + (a3 ? "a" : "b") +
		                   "' is 3D; both shapes of a request are 2D or both 3D");
	if (a3)
		return Answer3(request, mode, method);
	if (mode == "toi")
		return AnswerTimeOfImpact(request, id);
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
	WriteContact(out, c);
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

const char* ContactToolSummary()
{
	return "b2a_contact: contact detection between analytic particles, JSON Lines in, JSON Lines out.";
}

const char* ContactToolHelp()
{
	static const std::string text = std::string(ContactTool2dHelp()) + ContactTool3Help();
	return text.c_str();
}

const char* ContactTool2dHelp()
{
	return R"(Each input line is one JSON object (blank lines are skipped):
  {"id": <any JSON value>, "mode": "common" | "scale_a" | "contact" | "toi",
   "method": "auto" | "newton" | "grid", "a": <shape>, "b": <shape>, "t_max": T (toi only)}
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
