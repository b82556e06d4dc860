// b2analytic benchmark: numerical stability of the 3D contact solvers over random pairs.
//
// Most configurations are built with a known answer: A at a random pose, a point X on A's
// level-C surface, and B turned and placed so that its own level-C surface touches A's there
// with opposed normals. For convex shapes that point is the common level's unique solution, so
// the answer is known exactly (to the construction's rounding, ~1e-16) without any solver.
// Random poses are checked by a long-double Newton polish of the equations from the answer.
#include "BenchCommon.h"
#include "common/CommandLine.h"

#include "b2analytic/3d/Contact3.h"
#include "b2analytic/3d/SuperellipsoidShape.h"
#include "Reference3.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace b2a;
using demo::Json;
namespace r3 = b2a::test::ref3;

namespace
{
const char* kHelp = R"(b2a_stress3d: numerical stability of the 3D contact solvers on random pairs.

A million configurations (--quick: 40000) of superellipsoids, ellipsoids and spheres (aspect
ratio 1 to 100, exponents 2 to 20, integer or not and unequal, sizes 1e-3 to 1e3 with a size
ratio up to 10), most built with a known common level C and point: log-uniform C from 1e-3 to
1e3 (built), |C - 1| below 1e-9 (near_tangent), C from 1e-6 to 1e-2 (deep_overlap, one centre
deep inside the other), the same shape twice (identical); and the same shape at the same pose
(identical_pose) or two shapes at one centre (coincident), which have no level point and get
the axis of least overlap; and random poses (random, checked by a long-double Newton polish of
the equations from the answer). Each is solved by ComputeContact (the automatic path).

Writes DIR/stress3d_summary.json (per category: how many converged, converged after a fallback,
failed, gave a non-finite field or a wrong verdict, the largest level, point and normal errors,
how many were inaccurate beyond 1e-9 of the level or the size, the mean time of a contact, and
the worst case in full precision). Flat contacts (faces of high exponents touching face to
face, whose point the equations' rounding moves by more than 1e-9 of the size) and random poses
at a common level below 1e-9 (centres within a hair of each other) are counted apart as
ill_conditioned, their errors reported separately (a flat contact's level is still checked).
Exits 1 when any result fails, has a non-finite field, or gives the wrong touching verdict.
)";

enum class Category : int { built, nearTangent, deepOverlap, identical, identicalPose, coincident, random, count };
const char* CategoryName(Category c)
{
	static const char* names[] = {"built", "near_tangent", "deep_overlap", "identical", "identical_pose", "coincident", "random"};
	return names[int(c)];
}

struct Tally
{
	long configurations = 0, converged = 0, fallback = 0, failed = 0, nonFinite = 0, wrongVerdict = 0, inaccurate = 0, checked = 0;
	double worstLevel = 0.0, worstPoint = 0.0, worstNormal = 0.0;
	Json worstCase;
	double worstScore = -1.0;
	long flat = 0;                     // ill-conditioned configurations (flat faces, near-coincident centres), apart
	double flatLevel = 0.0, flatPoint = 0.0;
	double seconds = 0.0;              // time in ComputeContact
	std::map<std::string, long> methods; // answers per solver
	std::map<std::string, double> methodSeconds;
};

struct Random
{
	std::mt19937_64 engine;
	double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
	double LogUniform(double lo, double hi) { return std::exp(Uniform(std::log(lo), std::log(hi))); }
	Vec3 Unit()
	{
		std::normal_distribution<double> n(0.0, 1.0);
		return Normalize(Vec3(n(engine), n(engine), n(engine)));
	}
	Quat Rotation()
	{
		std::normal_distribution<double> n(0.0, 1.0);
		return Normalize(Quat(n(engine), n(engine), n(engine), n(engine)));
	}
};

std::shared_ptr<SuperellipsoidShape> RandomShape(Random& rng, double scale)
{
	const double a = scale, b = scale * rng.LogUniform(0.1, 10.0), c = scale * rng.LogUniform(0.1, 10.0);
	// Aspect at most 100 between the largest and smallest semi-axis.
	const double lo = std::min({a, b, c}), hi = std::max({a, b, c});
	const double squeeze = hi / lo > 100.0 ? std::log(100.0) / std::log(hi / lo) : 1.0;
	auto axis = [&](double v) { return lo * std::pow(v / lo, squeeze); };
	const double roll = rng.Uniform(0, 1);
	if (roll < 0.1)
		return MakeSphere(a);
	if (roll < 0.25)
		return MakeEllipsoid(axis(a), axis(b), axis(c));
	auto exponent = [&]() { return rng.Uniform(0, 1) < 0.5 ? std::round(rng.Uniform(2, 20)) : rng.Uniform(2, 20); };
	const double n1 = exponent();
	const bool equal = rng.Uniform(0, 1) < 0.3;
	return MakeSuperellipsoid(axis(a), axis(b), axis(c), n1, equal ? n1 : exponent(), equal ? n1 : exponent());
}

// The rotation taking the unit u onto the unit v (the shortest arc).
Quat Arc(Vec3 u, Vec3 v)
{
	const double d = Dot(u, v);
	if (d < -1.0 + 1e-12)
	{
		Vec3 axis = Cross(u, Vec3(1, 0, 0));
		if (LengthSquared(axis) < 1e-6)
			axis = Cross(u, Vec3(0, 1, 0));
		return AxisAngle(axis, kPi);
	}
	const Vec3 c = Cross(u, v);
	return Normalize(Quat(1.0 + d, c.x, c.y, c.z));
}

// A pair built with common level C at the world point X, A's outward normal n there.
struct Built
{
	std::shared_ptr<SuperellipsoidShape> a, b;
	Pose3 pa, pb;
	double level = 0.0;
	Vec3 point, normal;
};

Built Build(Random& rng, std::shared_ptr<SuperellipsoidShape> a, std::shared_ptr<SuperellipsoidShape> b, double C)
{
	Built p;
	p.a = std::move(a);
	p.b = std::move(b);
	p.level = C;
	p.pa = Pose3(Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)) * p.a->BoundingRadius(), rng.Rotation());
	const Vec3 xa = p.a->PointOnRay(rng.Unit(), C);
	p.point = ToWorld(p.pa, xa);
	p.normal = Normalize(Rotate(p.pa.q, p.a->Gradient(xa)));
	const Vec3 xb = p.b->PointOnRay(rng.Unit(), C);
	const Vec3 nb = Normalize(p.b->Gradient(xb));
	// B's outward normal at xb onto −n, then a random turn about −n.
	const Quat q = Normalize(AxisAngle(-p.normal, rng.Uniform(-kPi, kPi)) * Arc(nb, -p.normal));
	p.pb = Pose3(p.point - Rotate(q, xb), q);
	return p;
}

double Angle(Vec3 a, Vec3 b) { return std::atan2(Length(Cross(a, b)), Dot(a, b)); }

// How far the common level's point is determined along the surfaces: the solvers fix it by the
// tangential part of ∇λA + μ∇λB = 0, whose rounding (a few eps of |∇λA|) moves the point by that
// over κ, the least eigenvalue on the tangent plane of H = H_A + μH_B (world, μ balancing the
// gradients). Flat faces of high exponents touching face to face have κ near 0: their point is
// not determined to the tolerance, only their level is.
double PointUncertainty(const Built& p)
{
	const Vec3 xa = ToBody(p.pa, p.point), xb = ToBody(p.pb, p.point);
	const LevelDerivatives3 da = p.a->Derivatives(xa), db = p.b->Derivatives(xb);
	const double mu = Length(da.gradient) / Length(db.gradient);
	const Sym33 H = Rotate(ToMatrix(p.pa.q), da.hessian) + mu * Rotate(ToMatrix(p.pb.q), db.hessian);
	// An orthonormal basis (t1, t2) of the tangent plane, and the 2×2 block's least eigenvalue.
	const Vec3 n = p.normal;
	const Vec3 t1 = Normalize(Cross(n, std::fabs(n.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0))), t2 = Cross(n, t1);
	const double h11 = Dot(t1, H * t1), h12 = Dot(t1, H * t2), h22 = Dot(t2, H * t2);
	const double kappa = 0.5 * (h11 + h22) - std::sqrt(0.25 * (h11 - h22) * (h11 - h22) + h12 * h12);
	return 1e-14 * Length(da.gradient) / std::max(kappa, 1e-300);
}

bool AllFinite(const ContactResult3& c)
{
	return std::isfinite(c.level) && std::isfinite(c.separation) && IsFinite(c.point) && IsFinite(c.normal) && IsFinite(c.pointA) &&
	       IsFinite(c.pointB);
}

Json VecJson(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

Json CaseJson(const SuperellipsoidShape& a, const Pose3& pa, const SuperellipsoidShape& b, const Pose3& pb, const ContactResult3& c)
{
	return {{"a", a.Describe()},
	        {"pose_a", {{"p", VecJson(pa.p)}, {"q", Json::array({pa.q.w, pa.q.x, pa.q.y, pa.q.z})}}},
	        {"b", b.Describe()},
	        {"pose_b", {{"p", VecJson(pb.p)}, {"q", Json::array({pb.q.w, pb.q.x, pb.q.y, pb.q.z})}}},
	        {"status", StatusName(c.status)},
	        {"method", MethodName(c.method)},
	        {"failure", c.failure},
	        {"level", c.level},
	        {"point", VecJson(c.point)}};
}

// Records what every result must satisfy: an answer, finite fields, the verdict its level gives.
bool Basic(Tally& t, const ContactResult3& c)
{
	++t.configurations;
	++t.methods[MethodName(c.method)];
	if (!c.Ok())
	{
		++t.failed;
		return false;
	}
	(c.status == SolveStatus::converged ? t.converged : t.fallback)++;
	if (!AllFinite(c))
	{
		++t.nonFinite;
		return false;
	}
	if (c.method != SolveMethod::overlapAxis && (c.touching != (c.level <= 1.0) || c.touching != (c.separation <= 0.0)))
	{
		++t.wrongVerdict;
		return false;
	}
	return true;
}

// The automatic contact, timed, with Basic's checks; a failing one becomes the category's worst.
bool Solve(Tally& t, const SuperellipsoidShape& a, const Pose3& pa, const SuperellipsoidShape& b, const Pose3& pb, ContactResult3& c)
{
	// The thread's CPU time, which other work on the machine does not inflate.
	const double start = bench::ThreadCpuNanoseconds();
	c = ComputeContact(a, pa, b, pb);
	const double spent = 1e-9 * (bench::ThreadCpuNanoseconds() - start);
	t.seconds += spent;
	t.methodSeconds[MethodName(c.method)] += spent;
	if (Basic(t, c))
		return true;
	if (t.worstScore < 1e300)
	{
		t.worstScore = 1e300;
		t.worstCase = CaseJson(a, pa, b, pb, c);
	}
	return false;
}

void Errors(Tally& t, double level, double point, double normal, const Json& which)
{
	++t.checked;
	t.worstLevel = std::max(t.worstLevel, level);
	t.worstPoint = std::max(t.worstPoint, point);
	t.worstNormal = std::max(t.worstNormal, normal);
	if (level > 1e-9 || point > 1e-9)
		++t.inaccurate;
	const double score = std::max(level, point);
	if (score > t.worstScore)
	{
		t.worstScore = score;
		t.worstCase = which;
	}
}
} // namespace

int main(int argc, char** argv)
{
	long count = 0;
	demo::CommandLine cli("b2a_stress3d", kHelp);
	cli.Add("--count", count, 1000000, 40000, "N", "number of configurations (default 1000000, quick 40000)",
	        demo::WholeNumber(1, 1e9));
	const demo::DemoOptions opt = cli.Parse(argc, argv);
	demo::Progress progress("b2a_stress3d");
	Random rng{std::mt19937_64(opt.seed)};
	std::vector<Tally> tallies(int(Category::count));
	const auto start = std::chrono::steady_clock::now();
	for (long k = 0; k < count; ++k)
	{
		const int roll = int(k % 20);
		const Category cat = roll < 9    ? Category::built
		                     : roll < 12 ? Category::nearTangent
		                     : roll < 14 ? Category::deepOverlap
		                     : roll < 15 ? Category::identical
		                     : roll < 16 ? Category::identicalPose
		                     : roll < 17 ? Category::coincident
		                                 : Category::random;
		Tally& t = tallies[int(cat)];
		const double scale = rng.LogUniform(1e-3, 1e3);
		auto a = RandomShape(rng, scale);
		auto b = cat == Category::identical || cat == Category::identicalPose ? a : RandomShape(rng, scale * rng.LogUniform(0.1, 10.0));
		if (cat == Category::identicalPose || cat == Category::coincident || cat == Category::random)
		{
			const Pose3 pa(scale * Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)), rng.Rotation());
			Pose3 pb = cat == Category::identicalPose ? pa : Pose3(pa.p, rng.Rotation());
			if (cat == Category::random)
				pb.p = pa.p + rng.Uniform(0.05, 2.0) * (a->BoundingRadius() + b->BoundingRadius()) * rng.Unit();
			ContactResult3 c;
			if (!Solve(t, *a, pa, *b, pb, c))
				continue;
			if (cat != Category::random)
			{
				// No level point: the overlap axis, touching, the points on their surfaces.
				const bool sane = c.touching && c.separation < 0.0 && std::fabs(a->Level(ToBody(pa, c.pointA)) - 1.0) < 1e-9 &&
				                  std::fabs(b->Level(ToBody(pb, c.pointB)) - 1.0) < 1e-9;
				if (!sane)
					++t.wrongVerdict;
				continue;
			}
			// The long-double polish of the equations from the answer.
			const r3::Shape A(*a), B(*b);
			const r3::Pose la(pa), lb(pb);
			const r3::V3 X = r3::From(c.point);
			const r3::V3 ga = la.Rotate(A.Gradient(la.ToBody(X))), gb = lb.Rotate(B.Gradient(lb.ToBody(X)));
			r3::LD residual = 0.0L;
			const r3::SurfaceMinimum m = r3::Polish(A, la, B, lb, X, -r3::Dot(ga, gb) / r3::Dot(gb, gb), &residual);
			const double size = 0.5 * (a->BoundingRadius() + b->BoundingRadius());
			const double levelError = double(std::fabs((c.level - m.level) / m.level)), pointError = double(r3::Dist(c.point, m.point)) / size;
			if (m.level < 1e-9L)
			{
				// Centres within a hair of each other (in the levels' measure): ill-posed, apart.
				++t.flat;
				t.flatLevel = std::max(t.flatLevel, levelError);
				t.flatPoint = std::max(t.flatPoint, pointError);
				continue;
			}
			Errors(t, levelError, pointError, 0.0, CaseJson(*a, pa, *b, pb, c));
			continue;
		}
		double C = 1.0;
		if (cat == Category::built || cat == Category::identical)
			C = rng.LogUniform(1e-3, 1e3);
		else if (cat == Category::nearTangent)
			C = 1.0 + rng.Uniform(-1e-9, 1e-9);
		else
			C = rng.LogUniform(1e-6, 1e-2);
		const Built p = Build(rng, a, b, C);
		ContactResult3 c;
		if (!Solve(t, *p.a, p.pa, *p.b, p.pb, c))
			continue;
		const double size = 0.5 * (p.a->BoundingRadius() + p.b->BoundingRadius());
		if ((C <= 1.0) != c.touching && std::fabs(C - 1.0) > 1e-13)
			++t.wrongVerdict;
		Json which = CaseJson(*p.a, p.pa, *p.b, p.pb, c);
		which["exact_level"] = C;
		which["exact_point"] = VecJson(p.point);
		const double levelError = std::fabs(c.level - C) / C, pointError = Distance(c.point, p.point) / size;
		if (PointUncertainty(p) > 1e-9 * size)
		{
			// A flat contact: its level is checked, its point only as far as it is determined.
			++t.flat;
			t.flatLevel = std::max(t.flatLevel, levelError);
			t.flatPoint = std::max(t.flatPoint, pointError);
			Errors(t, levelError, 0.0, 0.0, which);
		}
		else
			Errors(t, levelError, pointError, Angle(c.normal, p.normal), which);
		if (k % 4096 == 0)
			progress.Report(double(k) / count, CategoryName(cat));
	}
	Json categories = Json::object();
	long bad = 0, total = 0, inaccurate = 0;
	double solveSeconds = 0.0;
	for (int i = 0; i < int(Category::count); ++i)
	{
		const Tally& t = tallies[i];
		bad += t.failed + t.nonFinite + t.wrongVerdict;
		total += t.configurations;
		inaccurate += t.inaccurate;
		solveSeconds += t.seconds;
		categories[CategoryName(Category(i))] = {{"configurations", t.configurations},
		                                         {"converged", t.converged},
		                                         {"converged_after_fallback", t.fallback},
		                                         {"failed", t.failed},
		                                         {"non_finite", t.nonFinite},
		                                         {"wrong_verdict", t.wrongVerdict},
		                                         {"checked", t.checked},
		                                         {"inaccurate_beyond_1e-9", t.inaccurate},
		                                         {"max_level_error", t.worstLevel},
		                                         {"max_point_error", t.worstPoint},
		                                         {"max_normal_error", t.worstNormal},
		                                         {"ill_conditioned", t.flat},
		                                         {"ill_conditioned_max_level_error", t.flatLevel},
		                                         {"ill_conditioned_max_point_error", t.flatPoint},
		                                         {"mean_contact_us", 1e6 * t.seconds / std::max(1L, t.configurations)},
		                                         {"answers_by_method", t.methods},
		                                         {"mean_us_by_method", [&t] {
			                                          Json m = Json::object();
			                                          for (const auto& [name, n] : t.methods)
				                                          m[name] = 1e6 * t.methodSeconds.at(name) / double(n);
			                                          return m;
		                                          }()},
		                                         {"worst_case", t.worstCase}};
	}
	const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	Json summary = {{"program", "b2a_stress3d"},
	                {"configurations", total},
	                {"seed", opt.seed},
	                {"failed_nonfinite_or_wrong", bad},
	                {"inaccurate_beyond_1e-9", inaccurate},
	                {"errors", "level: relative; point: relative to the pair's size (mean bounding radius); normal: radians"},
	                {"categories", categories},
	                {"solve_seconds", solveSeconds},
	                {"run_seconds", seconds},
	                {"machine", bench::MachineJson(bench::GetMachineInfo())}};
	demo::WriteJson(opt.out + "/stress3d_summary.json", summary);
	progress.Report(1.0, "done");
	std::printf("b2a_stress3d: %ld configurations, %ld failed, non-finite or wrong, %ld inaccurate beyond 1e-9, %.1f us a contact; "
	            "summary in %s/stress3d_summary.json\n",
	            total, bad, inaccurate, 1e6 * solveSeconds / std::max(1L, total), opt.out.c_str());
	return bad == 0 ? 0 : 1;
}
