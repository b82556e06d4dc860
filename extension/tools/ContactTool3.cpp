// b2analytic: b2a_contact requests with 3D shapes (superellipsoids, ellipsoids, spheres).
#include "ContactToolCommon.h"

#include "b2analytic/3d/SuperellipsoidShape.h"
#include "b2analytic/3d/TimeOfImpact3.h"

#include <memory>

namespace b2a::tool
{

namespace
{
struct ParsedShape3
{
	std::shared_ptr<const Shape3> shape;
	Motion3 motion; // pose at t = 0, velocity and angular velocity (toi only)
};


// The orientation: "quat" [w, x, y, z] (normalised where within 1e-6 of unit length), or
// "euler_zxz" [psi, theta, phi] (R = Rz(psi) Rx(theta) Rz(phi)), or the identity.
Quat ParseOrientation(const json& s, const std::string& path)
{
	if (s.contains("quat") && s.contains("euler_zxz"))
		throw RequestError("fields '" + path + "quat' and '" + path + "euler_zxz' both give the orientation: give one");
	if (s.contains("euler_zxz"))
	{
		const std::vector<double> e = Numbers(s, "euler_zxz", path, 3, true, {});
		return EulerZXZ(e[0], e[1], e[2]);
	}
	const std::vector<double> q = Numbers(s, "quat", path, 4, false, {1, 0, 0, 0});
	const Quat quat(q[0], q[1], q[2], q[3]);
	if (!(std::fabs(Norm(quat) - 1.0) <= 1e-6))
		throw RequestError("field '" + path + "quat' must be a unit quaternion [w, x, y, z] (norm 1 within 1e-6), got " +
		                   s["quat"].dump());
	return Normalize(quat);
}

ParsedShape3 ParseShape3(const json& request, const std::string& key, bool motion)
{
	const std::string type = ShapeType(request, key);
	const json& s = request[key];
	const std::string path = key + ".";
	std::set<std::string> common = {"type", "x", "y", "z", "quat", "euler_zxz"};
	if (motion)
		common.insert({"v", "w"});
	auto allowed = [&](std::initializer_list<const char*> own) {
		std::set<std::string> keys = common;
		for (const char* k : own)
			keys.insert(k);
		return keys;
	};
	ParsedShape3 out;
	try
	{
		if (type == "superellipsoid")
		{
			CheckKeys(s, allowed({"a", "b", "c", "n"}), path, "a superellipsoid");
			std::vector<double> n;
			if (s.contains("n") && s["n"].is_number())
				n.assign(3, Number(s, "n", path, true, 0));
			else
				n = Numbers(s, "n", path, 3, true, {});
			out.shape = MakeSuperellipsoid(Number(s, "a", path, true, 0), Number(s, "b", path, true, 0), Number(s, "c", path, true, 0),
			                               n[0], n[1], n[2]);
		}
		else if (type == "ellipsoid")
		{
			CheckKeys(s, allowed({"a", "b", "c"}), path, "an ellipsoid");
			out.shape = MakeEllipsoid(Number(s, "a", path, true, 0), Number(s, "b", path, true, 0), Number(s, "c", path, true, 0));
		}
		else if (type == "sphere")
		{
			CheckKeys(s, allowed({"r"}), path, "a sphere");
			out.shape = MakeSphere(Number(s, "r", path, true, 0));
		}
		else
			throw RequestError("field '" + path + "type': unknown 3D shape type \"" + type +
			                   "\" (expected superellipsoid, ellipsoid or sphere; both shapes of a request are 2D or both 3D)");
	}
	catch (const InvalidParameter& e)
	{
		throw RequestError("shape '" + key + "': " + e.what()); // the shape's message names its field
	}
	out.motion.pose = Pose3(Vec3(Number(s, "x", path, false, 0), Number(s, "y", path, false, 0), Number(s, "z", path, false, 0)),
	                        ParseOrientation(s, path));
	const std::vector<double> v = Numbers(s, "v", path, 3, false, {0, 0, 0}), w = Numbers(s, "w", path, 3, false, {0, 0, 0});
	out.motion.velocity = Vec3(v[0], v[1], v[2]);
	out.motion.angularVelocity = Vec3(w[0], w[1], w[2]);
	return out;
}

bool Finite(const ContactResult3& c)
{
	return std::isfinite(c.level) && IsFinite(c.point) && IsFinite(c.normal) && IsFinite(c.pointA) && IsFinite(c.pointB) &&
	       std::isfinite(c.separation);
}
} // namespace

json Answer3(const json& request, const std::string& mode, const std::string& method)
{
	MethodChoice choice = MethodChoice::automatic;
	if (method == "newton")
		choice = MethodChoice::newton;
	else if (method == "grid")
		choice = MethodChoice::grid;
	const bool toi = mode == "toi";
	const ParsedShape3 a = ParseShape3(request, "a", toi), b = ParseShape3(request, "b", toi);
	const Shape3 &sa = *a.shape, &sb = *b.shape;
	const Pose3 &pa = a.motion.pose, &pb = b.motion.pose;
	json out;
	out["id"] = request.contains("id") ? request["id"] : json(nullptr);
	out["status"] = "ok";
	out["mode"] = mode;
	if (toi)
	{
		const double tMax = Number(request, "t_max", "", true, 0);
		if (!(tMax >= 0.0))
			throw RequestError("field 't_max' must be >= 0, got " + request["t_max"].dump());
		const TimeOfImpactResult3 r = TimeOfImpact(sa, a.motion, sb, b.motion, tMax, ToolTimeOfImpactOptions());
		if (!r.Ok())
			throw TimeOfImpactError(r.failure, r.iterations, request);
		if (!Finite(r.contact) || !std::isfinite(r.time))
			throw RequestError("solver returned a non-finite value");
		WriteTimeOfImpact(out, r);
		return out;
	}
	ContactResult3 c;
	if (mode == "contact")
		c = ComputeContact(sa, pa, sb, pb, choice);
	else
	{
		const LevelResult3 level = mode == "common" ? SolveCommonLevel(sa, pa, sb, pb, choice) : SolveScaleA(sa, pa, sb, pb, choice);
		if (!level.Ok())
			throw RequestError(std::string("solver failed (") + MethodName(level.method) + "): " + level.failure);
		c = ContactFromLevel(sa, pa, sb, pb, level, level.level <= 1.0, mode == "scale_a");
		c.normal = level.normal; // these modes report ∇λA's direction at the point
	}
	if (!c.Ok())
		throw RequestError(std::string("solver failed (") + MethodName(c.method) + "): " + c.failure);
	if (!Finite(c))
		throw RequestError("solver returned a non-finite value");
	WriteContact(out, c);
	return out;
}

const char* ContactTool3Help()
{
	return R"(
3D shapes (both shapes of a request 2D, or both 3D):
  {"type": "superellipsoid", "a": A, "b": B, "c": C, "n": [N1, N2, N3], "x": X, "y": Y, "z": Z,
   "quat": [W, QX, QY, QZ]}     |x/a|^n1 + |y/b|^n2 + |z/c|^n3 <= 1, every exponent >= 1
                                ("n": N alone for three equal exponents)
  {"type": "ellipsoid", "a": A, "b": B, "c": C, ...}
  {"type": "sphere", "r": R, ...}
x, y, z default to 0; the orientation (body to world) is "quat", a unit quaternion [w, x, y, z],
or "euler_zxz": [psi, theta, phi] with R = Rz(psi) Rx(theta) Rz(phi); the identity without
either. The answers carry 3-vectors: "point": [X, Y, Z], "normal", "point_a", "point_b".
Modes common, scale_a and contact as in 2D (common: every 3D shape is convex); methods auto
(spheres in closed form, ellipsoids by Perram-Wertheim, smooth superellipsoids by Newton with the
min-max and grid fallbacks, exponents below 2 by the grid), newton, grid.

Mode toi (2D and 3D): the first time in [0, t_max] at which the particles touch, each moving with
constant linear and angular velocity about its centre: the request carries "t_max": T (>= 0),
each shape "v" (linear velocity: [VX, VY] in 2D, [VX, VY, VZ] in 3D) and "w" (angular velocity:
a number, counter-clockwise, in 2D; a world-frame vector [WX, WY, WZ] in 3D), both 0 by default;
x, y, (z,) angle or quat give the pose at t = 0. The answer:
  {"id": ..., "status": "ok", "mode": "toi", "time": T or null, "method": ..., "scale": C,
   "point": [..], "normal": [..], "point_a": [..], "point_b": [..], "separation": S,
   "touching": true, "iterations": K}
with "time", "point" and "normal" the first contact's (exact: conservative advancement, then a
root of the separation in time to 1e-13 relative); "time": null when they do not touch before
t_max, then "point" and "normal" are null and "separation_at_t_max" is the gap at t_max.
Conservative advancement takes at most 200 steps of gap / (approach speed bound) each; a motion
that needs more (a fast spin kept near the other particle over a long t_max) gets an error that
says so: ask for a shorter t_max.
Example (the paper's Figure 17: mm, ms, rad/ms; first contact at t = 0.1923 ms):
  {"id":17,"mode":"toi","t_max":1,
   "a":{"type":"superellipsoid","a":4,"b":4,"c":4,"n":[6,6,12],"x":-10,"y":-15,"z":-10,
        "euler_zxz":[0.3490658503988659,0.39269908169872414,0.4487989505128276],"v":[-20,-10,-15],"w":[20,-30,2]},
   "b":{"type":"superellipsoid","a":2,"b":3,"c":2,"n":8,"x":-20,"y":-25,"z":-20,
        "euler_zxz":[0.5235987755982988,0.6283185307179586,0.7853981633974483],"v":[10,20,15],"w":[-10,20,-2]}}
)";
}

} // namespace b2a::tool
