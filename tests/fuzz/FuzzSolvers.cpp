// b2analytic fuzzing: the contact solvers with any shape parameters and poses.
//
// Two shapes and their poses come from the bytes (extreme and non-finite values included), then
// every solver of the public API runs on them: ComputeContact and SolveCommonLevel with each
// MethodChoice, SolveScaleA, SolveGridScale, TimeOfImpact, the polygon contact and its manifold,
// and the single-shape queries (TestPoint, RayCast, FirstSurfaceCrossing, support, AABB).
// Shape constructors may reject parameters with InvalidParameter; any other exception, crash,
// hang or sanitizer report is a bug. With finite input every answer must be finite or an
// explicit failure, and no field may be NaN even then (ContactResult.h).
#include "FuzzShapes.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

using namespace b2a;
using namespace b2a::fuzz;

namespace
{
// Solver options within their documented ranges, with caps so that one input stays fast.
SolverOptions DecodeOptions(FuzzInput& in)
{
	SolverOptions o;
	if (in.Bool())
	{
		o.maxIterations = in.Int(1, 80);
		o.gridSamples = 8 << in.Int(0, 6); // 8 to 512
		o.gridCandidates = in.Int(1, 8);
	}
	return o;
}

// A hit is a touching contact, or a grazing one: conservative advancement stops where its lower
// bound of the distance falls below 1e-12 of the pair's size (TimeOfImpact.h). Known failure, not
// fixed yet: where that bound is loose the search reports a hit while the particles are still
// apart (tests/contact/FuzzRegressionTests.cpp, should_fail); it is printed, not trapped, so that
// the fuzzer goes on looking for other bugs.
void CheckTimeOfImpact(const TimeOfImpactResult& t, double tMax, double size, bool ordinary)
{
	B2A_FUZZ_CHECK(t.failure != nullptr && !std::isnan(t.time));
	Context() += "| toi: hit=" + std::to_string(t.hit) + " time=" + FormatNumber(t.time) + " separation=" +
	             FormatNumber(t.contact.separation) + " contact " + StatusName(t.contact.status) + " '" + t.contact.failure +
	             "' iterations=" + std::to_string(t.iterations);
	CheckContact(t.contact, ordinary);
	if (!t.Ok())
		return;
	B2A_FUZZ_CHECK(t.time >= 0.0 && t.time <= tMax);
	// Far beyond ordinary sizes and speeds the contact at the end may fail to overflow (a failure
	// that says so); for ordinary input a converged search ends on a solved contact. Known
	// failure: a user shape beside a circle whose common level Newton and min-max miss and whose
	// grid answer is no solution (the level chain then fails with the grid's reason rather than
	// answer it as converged). It is printed, not trapped.
	const bool gridStoppedShort = !t.contact.Ok() && std::strstr(t.contact.failure, "grid: stopped short") != nullptr;
	if (ordinary && gridStoppedShort)
		std::fprintf(stderr, "b2a fuzz known failure: the level chain's grid stopped short\ninput: %s\n", Context().c_str());
	B2A_FUZZ_CHECK(t.contact.Ok() || !ordinary || gridStoppedShort);
	if (t.hit && !t.contact.touching && t.contact.separation > 1e-9 * size)
		std::fprintf(stderr, "b2a fuzz known failure: time of impact hit while apart\ninput: %s\n", Context().c_str());
}

// The queries on one posed shape: point test, ray cast, line crossing, support, AABB.
void RunQueries(FuzzInput& in, const Shape& s, const Pose& pose, bool finite)
{
	const double R = s.BoundingRadius();
	const Vec2 p1 = pose.p + R * Vec2(in.Number(-3.0, 3.0), in.Number(-3.0, 3.0));
	const Vec2 p2 = pose.p + R * Vec2(in.Number(-3.0, 3.0), in.Number(-3.0, 3.0));
	const double maxFraction = in.Number(0.0, 1.0);
	const bool queryFinite = finite && IsFinite(p1) && IsFinite(p2) && std::isfinite(maxFraction);
	(void)TestPoint(s, pose, p1);
	const RayHit hit = RayCast(s, pose, p1, p2, maxFraction);
	const double t = FirstSurfaceCrossing(s, pose, p1, p2 - p1, in.Number(0.0, 2.0));
	const Vec2 support = WorldSupport(s, pose, p2 - p1);
	const Box box = s.ComputeAABB(pose);
	if (!queryFinite)
		return;
	B2A_FUZZ_CHECK(!std::isnan(t) && (t == -1.0 || t >= 0.0));
	if (hit.hit)
	{
		B2A_FUZZ_CHECK(hit.fraction >= 0.0 && hit.fraction <= maxFraction);
		B2A_FUZZ_CHECK(IsFinite(hit.point) && IsFinite(hit.normal));
	}
	B2A_FUZZ_CHECK(NotNaN(support));
	B2A_FUZZ_CHECK(NotNaN(box.lower) && NotNaN(box.upper) && box.lower.x <= box.upper.x && box.lower.y <= box.upper.y);
}

// A convex polygon (or segment) near A: a regular one with 2 to 8 vertices.
void RunPolygon(FuzzInput& in, const Shape& a, const Pose& pa, double scale, bool finite)
{
	const int count = in.Int(2, 8);
	const double radius = scale * in.Positive(0.05, 5.0);
	const Pose pb = DecodePose(in, scale, 2.0);
	Vec2 v[8];
	for (int i = 0; i < count; ++i)
	{
		const double t = 2.0 * kPi * i / count;
		v[i] = radius * Vec2(std::cos(t), std::sin(t));
	}
	const ContactResult c = ComputePolygonContact(a, pa, v, count, pb);
	const bool polygonFinite = finite && IsFinite(pb) && std::isfinite(radius);
	if (polygonFinite)
		CheckContact(c, !in.AnyExtreme());
	if (!c.Ok())
		return;
	Vec2 world[8];
	for (int i = 0; i < count; ++i)
		world[i] = ToWorld(pb, v[i]);
	ManifoldSide sa;
	sa.shape = &a;
	sa.pose = pa;
	sa.point = !a.IsConvex();
	ManifoldSide sb;
	sb.vertices = world;
	sb.count = count;
	const double tol = in.Positive(1e-4, 0.1) * scale, minWidth = in.Uniform(0.0, 1.0) * scale;
	const ContactManifold m = BuildContactManifold(c, sa, sb, tol, minWidth);
	// Twice more through one cache, as on consecutive steps: the second call takes the faces the
	// first found.
	ManifoldCache cache;
	const ContactManifold first = BuildContactManifold(c, sa, sb, tol, minWidth, 0.0, &cache);
	const ContactManifold second = BuildContactManifold(c, sa, sb, tol, minWidth, 0.0, &cache);
	if (!polygonFinite)
		return;
	for (const ContactManifold* k : {&m, &first, &second})
	{
		B2A_FUZZ_CHECK(k->count >= 0 && k->count <= 2);
		for (int i = 0; i < k->count; ++i)
			B2A_FUZZ_CHECK(IsFinite(k->points[i].pointB) && k->points[i].separation <= 0.0);
	}
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	FuzzInput in(data, size);
	Context().clear();
	ShapePtr a, b;
	try
	{
		a = DecodeShape(in);
		Trace("shape");
		b = DecodeShape(in);
		Trace("shape");
	}
	catch (const InvalidParameter&)
	{
		return 0; // rejected with a message that names the field (the geometry tests check the text)
	}
	const double scale = a->BoundingRadius() + b->BoundingRadius();
	const Pose pa = DecodePose(in, scale, 2.0);
	const Pose pb = DecodePose(in, scale, 2.0);
	const SolverOptions options = DecodeOptions(in);
	const bool finite = IsFinite(pa) && IsFinite(pb) && std::isfinite(scale);
	const bool ordinary = !in.AnyExtreme();
	Trace("decoded");

	for (MethodChoice m : {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid})
	{
		WarmStart warm;
		const ContactResult c = ComputeContact(*a, pa, *b, pb, m, options, &warm);
		Trace("ComputeContact");
		const LevelResult common = SolveCommonLevel(*a, pa, *b, pb, m, options, &warm);
		Trace("SolveCommonLevel");
		const LevelResult scaleA = SolveScaleA(*a, pa, *b, pb, m, options);
		Trace("SolveScaleA");
		if (finite)
		{
			CheckContact(c, ordinary);
			CheckLevel(common, ordinary);
			CheckLevel(scaleA, ordinary);
		}
		// Warm-started again from the previous answer, as the Box2D adapter does every step.
		const ContactResult again = ComputeContact(*a, pa, *b, pb, m, options, &warm);
		Trace("ComputeContact (warm)");
		if (finite)
			CheckContact(again, ordinary);
	}
	// B held at another level; level 0 and below are degenerate (B shrinks to its centre or
	// vanishes), so only positive levels are held to the promises.
	const double levelB = in.Positive(0.05, 4.0) * b->SurfaceLevel();
	const LevelResult held = SolveGridScale(*a, pa, *b, pb, options, levelB);
	Trace("SolveGridScale");
	if (finite && std::isfinite(levelB) && levelB > 0.0)
		CheckLevel(held, !in.AnyExtreme());

	// Time of impact, with a step cap so that one input stays fast.
	Motion ma, mb;
	ma.pose = pa;
	mb.pose = pb;
	ma.velocity = scale * Vec2(in.Number(-5.0, 5.0), in.Number(-5.0, 5.0));
	mb.velocity = scale * Vec2(in.Number(-5.0, 5.0), in.Number(-5.0, 5.0));
	ma.angularVelocity = in.Number(-10.0, 10.0);
	mb.angularVelocity = in.Number(-10.0, 10.0);
	const double tMax = in.Number(0.0, 2.0);
	Context() += "motions vA=(" + FormatNumber(ma.velocity.x) + ", " + FormatNumber(ma.velocity.y) + ") vB=(" +
	             FormatNumber(mb.velocity.x) + ", " + FormatNumber(mb.velocity.y) + ") wA=" + FormatNumber(ma.angularVelocity) +
	             " wB=" + FormatNumber(mb.angularVelocity) + " tMax=" + FormatNumber(tMax) + " ";
	TimeOfImpactOptions toi;
	toi.maxIterations = 200;
	toi.solver = options;
	const TimeOfImpactResult t = TimeOfImpact(*a, ma, *b, mb, tMax, toi);
	Trace("TimeOfImpact");
	if (finite && IsFinite(ma.velocity) && IsFinite(mb.velocity) && std::isfinite(ma.angularVelocity) &&
	    std::isfinite(mb.angularVelocity) && std::isfinite(tMax) && tMax >= 0.0)
		CheckTimeOfImpact(t, tMax, scale, !in.AnyExtreme());

	RunQueries(in, *a, pa, finite);
	Trace("queries");
	RunPolygon(in, *a, pa, scale, finite);
	Trace("polygon");
	return 0;
}
