// b2analytic: one- and two-point manifolds from a contact.
//
// Box2D's boxes rest on two points because their faces are flat and fixed in the body: the
// manifold's normal is the reference face's, its points are the incident face's ends clipped to
// the reference face, and a point that lifts above the reference face is dropped. A tilted box
// thus stands on its lower corner and gravity turns it back flat. Blocky analytic shapes have
// faces too, flat to within Box2D's slop over much of their sides, and the manifold here is built
// the same way from them: a face is the arc around a point of the surface whose radius of
// curvature is large against the particle (its flattest point), within the tolerance of the
// tangent there. It belongs to the body, as a box's face does, so a tilted particle's face ends
// lie at different depths and the higher one lifts off. (Arcs within the tolerance of each
// particle's extreme along the contact normal would not do: their ends always lie at the same
// depth, so a particle stands on them at any small tilt, a foot that freezes whatever tilt a
// pile left it with.) The normal is A's face normal: fixed in A's frame, it does not turn with
// the small rotations that move the contact point of two nearly flat faces along them.
#include "b2analytic/ContactManifold.h"

#include "b2analytic/SuperellipseShape.h"
#include "b2analytic/SurfaceQueries.h"
#include "contact/OverlapParts.h"
#include "contact/SolverCore.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace b2a
{

namespace
{
// A face of one side in world coordinates: its outward unit normal, a point of its plane (on the
// surface), and its two ends.
struct Face
{
	bool valid = false;
	Vec2 normal;
	Vec2 centre;
	Vec2 ends[2];
};

// Curvature of the level curve through the body point x (1/length): t·H·t/|∇λ| with t the
// unit tangent. +∞ where the gradient vanishes or anything is not finite (no claim of flatness).
double LevelCurvature(const Shape& shape, Vec2 x)
{
	const LevelDerivatives ld = shape.Derivatives(x);
	const double g = Length(ld.gradient);
	if (!(g > 0.0) || !std::isfinite(g))
		return std::numeric_limits<double>::infinity();
	const Vec2 t = Perp(ld.gradient) / g;
	const double kappa = Dot(t, ld.hessian * t) / g;
	return std::isfinite(kappa) ? kappa : std::numeric_limits<double>::infinity();
}

// A face's flattest point has a radius of curvature above ten bounding radii R (κR ≤ 0.1):
// a blocky superellipse's sides have one (the curvature vanishes on the axis and grows as
// |x|^(n−2) towards the corners); a circle and an ellipse of aspect below ten do not (κR = b/a
// at an ellipse's flattest point). Those keep one manifold point: two points on a curved
// surface would make a foot, and hold up an ellipse balanced on another that physics says must
// roll off.
constexpr double kFlatCurvature = 0.1;

// Whether the shape can have a face at all: an ellipse's flattest point, the end of its minor
// axis, has κR = b/a (circles 1), so only needles of aspect ten and more have one; decided once
// here instead of by curvatures at every step of every contact (most of a hopper's).
bool CanHaveFaces(const Shape& shape)
{
	const SuperellipseShape* e = AsPlainEllipse(shape);
	if (!e)
		return true;
	return std::min(e->A(), e->B()) <= kFlatCurvature * std::max(e->A(), e->B());
}

// Whether the surface point x (body frame) may lie on a face, before the search for one: it is
// flat enough itself, or the points where its arc within the tolerance would end if the surface
// were the parabola of x's curvature (√(2·tol/κ) either way along the tangent) are, with a
// margin of two. A circle's or an ellipse's arc is as curved throughout and fails here; a blocky
// particle's shoulder flattens towards its face and passes.
bool MayReachFace(const Shape& shape, Vec2 x, double tol)
{
	const double limit = 2.0 * kFlatCurvature / shape.BoundingRadius();
	const double kappa = LevelCurvature(shape, x);
	if (!(kappa > limit))
		return true;
	if (!std::isfinite(kappa))
		return false;
	const Vec2 t = Perp(Normalize(shape.Gradient(x)));
	const double reach = std::sqrt(2.0 * tol / kappa);
	return LevelCurvature(shape, x + reach * t) <= limit || LevelCurvature(shape, x - reach * t) <= limit;
}

// The polar angles (body frame) of the two ends of the arc of a convex shape whose points lie
// within tol of its extreme along the body direction db, q being the support point along it:
// the end on the clockwise side first. Each is bracketed by steps that double from π/64 and
// found by Brent's method to 1e-10 rad (1e-10 of the size, far below Box2D's float points).
// False where the arc reaches half a turn either way (no end to bound) or q is not the extreme.
bool ArcEnds(const Shape& shape, Vec2 db, Vec2 q, double tol, double ends[2])
{
	const double h = Dot(q, db);
	const double ts = std::atan2(q.y, q.x);
	// excess(θ) = (h − x(θ)·d) − tol, angles measured from ts: ≤ 0 on the arc.
	auto excess = [&](double relative) { return (h - Dot(shape.SurfacePoint(ts + relative), db)) - tol; };
	const double atSupport = excess(0.0);
	if (!(atSupport <= 0.0))
		return false;
	for (int side = 0; side < 2; ++side)
	{
		const double dir = side == 0 ? -1.0 : 1.0;
		double inner = 0.0, fin = atSupport, outer = 0.0, fout = 0.0, step = kPi / 64.0;
		for (outer = dir * step, fout = excess(outer); fout <= 0.0; outer += dir * step, fout = excess(outer))
		{
			inner = outer;
			fin = fout;
			step *= 2.0;
			if (std::fabs(outer) > kPi)
				return false;
		}
		ends[side] = ts + FindRootBrent(excess, inner, outer, fin, fout, 1e-10, 100).x;
	}
	return true;
}

// A smooth convex shape's face nearest its surface point at the polar angle t0, as polar angles
// (body frame): face[0] its flattest point, face[1] and face[2] its ends; false where there is
// none. The flattest point is where the curvature, descending from t0 along the surface (steps that
// double from 0.01 rad, within a quarter turn), has its minimum (Brent's method, to 1e-8 rad; the
// face's normal moves by the curvature times that, nothing at a flat point).
bool FindFace(const Shape& shape, double t0, double tol, double face[3])
{
	auto kappa = [&](double theta) { return LevelCurvature(shape, shape.SurfacePoint(theta)); };
	const double k0 = kappa(t0), h = 0.01;
	const double kPlus = kappa(t0 + h), kMinus = kappa(t0 - h);
	double lo = t0 - h, hi = t0 + h;
	if (!(k0 <= kPlus && k0 <= kMinus))
	{
		// Downhill until the curvature rises again: the minimum lies between the last two steps.
		const double dir = kPlus < kMinus ? 1.0 : -1.0;
		double before = t0, at = t0 + dir * h, kAt = std::min(kPlus, kMinus), step = h;
		for (;;)
		{
			step *= 2.0;
			if (std::fabs(at + dir * step - t0) > 0.5 * kPi)
				return false;
			const double next = at + dir * step, kNext = kappa(next);
			if (!(kNext < kAt))
			{
				lo = std::min(before, next);
				hi = std::max(before, next);
				break;
			}
			before = at;
			at = next;
			kAt = kNext;
		}
	}
	const ScalarResult m = MinimizeBrent(kappa, lo, hi, 1e-8, 1e-10, 100);
	if (!(m.fx * shape.BoundingRadius() <= kFlatCurvature))
		return false;
	const Vec2 c = shape.SurfacePoint(m.x);
	double ends[2];
	if (!ArcEnds(shape, Normalize(shape.Gradient(c)), c, tol, ends))
		return false;
	face[0] = m.x;
	face[1] = ends[0];
	face[2] = ends[1];
	return true;
}

// An angle reduced to [−π, π]: std::remainder(d, 2π), without the library call where |d| ≤ π.
// There it is d itself, exactly: the remainder is d − k·2π with k the integer nearest d/2π, 0
// for |d| < π, and 0 too at the tie |d| = π (ties go to the even k). A kept face's three
// differences and an off-face contact's one lie within π nearly always.
inline double TurnRemainder(double d) { return std::fabs(d) <= kPi ? d : std::remainder(d, 2.0 * kPi); }

// Whether the body point at polar angle theta lies on the face (angles as FindFace gives them).
bool OnFace(const double face[3], double theta)
{
	const double at = TurnRemainder(theta - face[0]);
	return at >= TurnRemainder(face[1] - face[0]) && at <= TurnRemainder(face[2] - face[0]);
}

} // namespace

// A superellipse's faces for one patch tolerance, found once per shape: FindFace from each end of
// its axes (the particle is symmetric about both, and a blocky one's flattest points are there),
// with the body points that a kept face's test and the manifold read (its centre, normal and
// ends), which a contact would otherwise evaluate at every step. Where the table is complete, a
// contact's face is the table's face its point lies on, with no search; elsewhere a face found
// at a contact whose flattest point lies within kFaceSnap of one of these is taken to be it (both
// are the same curvature minimum, found to 1e-8 rad). Deterministic (found from the axes, not
// from whichever contact came first), so threads do not change it.
struct FaceTable
{
	struct Entry
	{
		double angles[3]; // as FindFace gives them
		Vec2 centre, normal, ends[2];
	};
	double tol = 0.0;
	int count = 0;
	Entry faces[4];
	// Whether the table holds every face: each lies at an axis end and the curvature rises and
	// falls once between neighbouring axis ends, so that FindFace from any point descends to one.
	bool complete = false;
};

namespace
{
constexpr double kFaceSnap = 1e-5; // rad; a blocky particle's face spans about 0.1 rad or more

FaceTable BuildFaceTable(const Shape& shape, double tol)
{
	FaceTable table;
	table.tol = tol;
	for (int k = 0; k < 4; ++k)
	{
		double face[3];
		if (!FindFace(shape, k == 3 ? -0.5 * kPi : 0.5 * kPi * k, tol, face))
			continue;
		bool known = false;
		for (int j = 0; j < table.count; ++j)
			known = known || std::fabs(TurnRemainder(face[0] - table.faces[j].angles[0])) <= kFaceSnap;
		if (known)
			continue;
		FaceTable::Entry& e = table.faces[table.count++];
		std::copy(face, face + 3, e.angles);
		e.centre = shape.SurfacePoint(face[0]);
		e.normal = Normalize(shape.Gradient(e.centre));
		e.ends[0] = shape.SurfacePoint(face[1]);
		e.ends[1] = shape.SurfacePoint(face[2]);
	}
	// Complete where every face found lies at the axis end it was searched from and the
	// curvature over a quadrant (the others are its mirror images) has a single maximum inside
	// it, sampled 32 times. (A table is built per shape, and a packing has a shape a particle.)
	table.complete = true;
	for (int j = 0; j < table.count; ++j)
	{
		const double c = table.faces[j].angles[0], quarter = 0.5 * kPi;
		table.complete = table.complete && std::fabs(c - quarter * std::nearbyint(c / quarter)) <= kFaceSnap;
	}
	const int samples = 32;
	int turns = 0; // changes of the curvature's direction along the quadrant
	double before = LevelCurvature(shape, shape.SurfacePoint(0.0)), slope = 0.0;
	for (int i = 1; i <= samples && table.complete; ++i)
	{
		const double kappa = LevelCurvature(shape, shape.SurfacePoint(0.5 * kPi * double(i) / samples));
		const double d = kappa - before;
		if (!std::isfinite(d))
			table.complete = false;
		else if (d != 0.0)
		{
			turns += slope != 0.0 && (d > 0.0) != (slope > 0.0) ? 1 : 0;
			slope = d;
		}
		before = kappa;
	}
	table.complete = table.complete && turns <= 1;
	return table;
}
} // namespace

// The shape's cache of face tables (its private members, this struct its friend).
struct FaceTableCache
{
	static const FaceTable* Get(const Shape& shape, double tol)
	{
		if (shape.Kind() != BuiltinKinds::superellipse)
			return nullptr;
		// Entries are never removed, so a pointer to one stays valid with the shape.
		const FaceTable* last = shape.m_lastFaceTable.load(std::memory_order_acquire);
		if (last && last->tol == tol)
			return last;
		{
			std::lock_guard<std::mutex> lock(shape.m_sampleMutex);
			for (const auto& entry : shape.m_faceTables)
				if (entry->tol == tol)
				{
					shape.m_lastFaceTable.store(entry.get(), std::memory_order_release);
					return entry.get();
				}
		}
		// Built outside the lock (FindFace evaluates the shape); a table another thread built
		// meanwhile for the same tolerance is the same, and the first one kept wins.
		auto made = std::make_shared<const FaceTable>(BuildFaceTable(shape, tol));
		std::lock_guard<std::mutex> lock(shape.m_sampleMutex);
		const FaceTable* found = nullptr;
		for (const auto& entry : shape.m_faceTables)
			if (entry->tol == tol)
				found = entry.get();
		if (!found)
		{
			found = made.get();
			shape.m_faceTables.push_back(std::move(made));
		}
		shape.m_lastFaceTable.store(found, std::memory_order_release);
		return found;
	}
};

namespace
{
// The table's entry for a kept face (its angles exactly the entry's), or null.
const FaceTable::Entry* TableEntry(const FaceTable* table, const double face[3])
{
	if (!table)
		return nullptr;
	for (int j = 0; j < table->count; ++j)
	{
		const FaceTable::Entry& e = table->faces[j];
		if (e.angles[0] == face[0] && e.angles[1] == face[1] && e.angles[2] == face[2])
			return &e;
	}
	return nullptr;
}

// Whether the body point x lies on the table's face: between its ends' rays (OnFace's test by
// the sides of the rays instead of by x's polar angle; a face spans less than half a turn).
bool InSector(const FaceTable::Entry& e, Vec2 x) { return Cross(e.ends[0], x) >= 0.0 && Cross(x, e.ends[1]) >= 0.0; }

// The table's face on which the body point x lies, or null.
const FaceTable::Entry* TableFaceAt(const FaceTable& table, Vec2 x)
{
	for (int j = 0; j < table.count; ++j)
		if (InSector(table.faces[j], x))
			return &table.faces[j];
	return nullptr;
}

// A face just found, replaced by the table's where its flattest point is one of the table's.
void SnapToTable(const FaceTable* table, double face[3])
{
	if (!table)
		return;
	for (int j = 0; j < table->count; ++j)
	{
		const FaceTable::Entry& e = table->faces[j];
		if (std::fabs(TurnRemainder(face[0] - e.angles[0])) <= kFaceSnap)
		{
			std::copy(e.angles, e.angles + 3, face);
			return;
		}
	}
}

// Whether the body point x lies within `gap` of the tangent plane at the face's flattest point:
// a contact point that was on the face at the last step stays on it while it lies within twice
// the tolerance, instead of leaving as soon as it passes an end (hysteresis). Two offset blocks
// whose faces overlap near both faces' ends otherwise go from two points to one and back every
// few steps, the normal turning and the second point's impulse lost each time, and keep their
// pile awake (docs/benchmarks.md, "Sleeping piles"). The face's ends, and so the manifold's
// points, stay those at the tolerance.
bool NearFacePlane(const Shape& shape, const FaceTable::Entry* entry, const double face[3], Vec2 x, double gap)
{
	const Vec2 c = entry ? entry->centre : shape.SurfacePoint(face[0]);
	const Vec2 n = entry ? entry->normal : Normalize(shape.Gradient(c));
	const double drop = Dot(c - x, n);
	return drop >= -gap && drop <= gap;
}

// A table's face of the side, in world coordinates (its normal and centre where `plane`).
Face TableSideFace(const ManifoldSide& side, const FaceTable::Entry& e, bool plane)
{
	Face out;
	out.valid = true;
	if (plane)
	{
		out.normal = Rotate(side.pose.q, e.normal);
		out.centre = ToWorld(side.pose, e.centre);
	}
	out.ends[0] = ToWorld(side.pose, e.ends[0]);
	out.ends[1] = ToWorld(side.pose, e.ends[1]);
	return out;
}

// The face of an analytic convex side at its contact point p (world) with outward direction d
// (world). Smooth shapes: the face through p, kept in `face` (angles) while the contact stays
// on it. Shapes with corners or infinite curvature on their axes (superellipse exponents below 2)
// have no curvature to tell faces by: their face is the arc within tol of their extreme along d,
// with d as its normal.
// `plane`: whether the caller reads the face's normal and centre (the reference face, A's); B's
// face gives its ends alone, and a smooth shape's kept face then takes two surface points, not
// three and a gradient. `wasOn`: the contact point lay on the kept face at the last step (in),
// and lies on it now (out).
Face AnalyticSideFace(const ManifoldSide& side, Vec2 p, Vec2 d, double tol, double face[3], bool& cached, double& offFace,
                      bool& wasOn, bool plane)
{
	const bool on = wasOn;
	wasOn = false;
	Face out;
	const Shape& shape = *side.shape;
	if (!shape.IsSmoothConvex())
	{
		const Vec2 db = InvRotate(side.pose.q, d);
		const Vec2 q = shape.Support(db);
		double ends[2];
		if (!ArcEnds(shape, db, q, tol, ends))
			return out;
		out.valid = true;
		out.normal = d;
		out.centre = ToWorld(side.pose, q);
		for (int k = 0; k < 2; ++k)
			out.ends[k] = ToWorld(side.pose, shape.SurfacePoint(ends[k]));
		return out;
	}
	if (!CanHaveFaces(shape))
		return out;
	const Vec2 x = ToBody(side.pose, p);
	const FaceTable* table = FaceTableCache::Get(shape, tol);
	if (table && table->complete)
	{
		// Every face is the table's: the kept one while the point stays on it (or near its plane,
		// as below), else the one the point lies on, with no search and no polar angle.
		const FaceTable::Entry* entry = cached ? TableEntry(table, face) : nullptr;
		if (!(entry && (InSector(*entry, x) || (on && NearFacePlane(shape, entry, face, x, 2.0 * tol)))))
		{
			entry = TableFaceAt(*table, x);
			cached = entry != nullptr;
			if (!entry)
				return out;
			std::copy(entry->angles, entry->angles + 3, face);
		}
		wasOn = true;
		return TableSideFace(side, *entry, plane);
	}
	// The contact point's polar angle, once: the kept face's test and the off-face record share it.
	const double theta = std::atan2(x.y, x.x);
	const FaceTable::Entry* entry = cached ? TableEntry(table, face) : nullptr;
	if (!(cached && (OnFace(face, theta) || (on && NearFacePlane(shape, entry, face, x, 2.0 * tol)))))
	{
		// Off the face kept (or none kept): a contact point that stays near where none was found
		// last time is taken to stay off faces, and a search runs only once it has moved on by
		// 0.01 rad (a tenth of a blocky particle's face, whose arrival at a face kept the check
		// above sees). In a settling pile most contacts on a blocky particle's rounded corners
		// were searched again at every step.
		if (std::fabs(TurnRemainder(theta - offFace)) < 0.01)
			return out;
		if (!MayReachFace(shape, x, tol) || !FindFace(shape, theta, tol, face))
			cached = false;
		else
		{
			cached = true;
			SnapToTable(table, face);
		}
		if (!(cached && OnFace(face, theta)))
		{
			offFace = theta;
			return out;
		}
		entry = TableEntry(table, face);
	}
	wasOn = true;
	out.valid = true;
	if (entry)
		return TableSideFace(side, *entry, plane);
	if (plane)
	{
		const Vec2 c = shape.SurfacePoint(face[0]);
		out.normal = Rotate(side.pose.q, Normalize(shape.Gradient(c)));
		out.centre = ToWorld(side.pose, c);
	}
	out.ends[0] = ToWorld(side.pose, shape.SurfacePoint(face[1]));
	out.ends[1] = ToWorld(side.pose, shape.SurfacePoint(face[2]));
	return out;
}

// The face of a polygon or segment facing d: the edge whose outward normal lies nearest d (it
// holds the polygon's extreme vertex along d), with the point p projected onto it as the point
// of its plane.
Face PolygonSideFace(const Vec2* w, int count, Vec2 p, Vec2 d)
{
	Face out;
	double best = -std::numeric_limits<double>::infinity();
	const int edges = count == 2 ? 1 : count;
	for (int j = 0; j < edges; ++j)
	{
		const Vec2 u = w[j], v = w[(j + 1) % count];
		const Vec2 outward = Normalize(Vec2(v.y - u.y, u.x - v.x)); // (counter-clockwise polygons)
		// A polygon's edge faces outwards; a segment's faces both ways.
		for (int side = 0; side < (count == 2 ? 2 : 1); ++side)
		{
			const Vec2 normal = side == 0 ? outward : -outward;
			if (LengthSquared(normal) > 0.0 && Dot(normal, d) > best)
			{
				best = Dot(normal, d);
				out.valid = true;
				out.normal = normal;
				out.centre = p - Dot(p - u, normal) * normal;
				out.ends[0] = u;
				out.ends[1] = v;
			}
		}
	}
	return out;
}

Face SideFace(const ManifoldSide& side, Vec2 p, Vec2 d, double tol, double face[3], bool& cached, double& offFace, bool& wasOn,
              bool plane = true)
{
	if (side.point)
		return {};
	if (side.shape)
		return side.shape->IsConvex() ? AnalyticSideFace(side, p, d, tol, face, cached, offFace, wasOn, plane) : Face{};
	if (side.vertices && side.count >= 2)
		return PolygonSideFace(side.vertices, side.count, p, d);
	return {};
}

// B's surface point on the line through p along n that is lowest along n (B's near side).
bool LowestAlong(const ManifoldSide& b, Vec2 p, Vec2 n, Vec2& out)
{
	if (b.shape)
	{
		// B's near crossing of the line is its far crossing of the reversed line, where B has one,
		// from the face point, which lies near B's surface (FarCrossingNear).
		double t = 0.0;
		if (b.shape->IsConvex() && b.shape->FarCrossingNear(ToBody(b.pose, p), InvRotate(b.pose.q, -n), t))
		{
			out = p - t * n;
			return true;
		}
		if (b.shape->IsConvex() && b.shape->LineMisses(ToBody(b.pose, p), InvRotate(b.pose.q, n)))
			return false; // what the search below finds, in closed form
		// Else start beyond B's support plane along −n (outside B) and enter along +n.
		const double low = -Dot(WorldSupport(*b.shape, b.pose, -n), n);
		const double margin = 1e-3 * b.shape->BoundingRadius() + 1e-12;
		const Vec2 start = p + (low - margin - Dot(p, n)) * n;
		const double sMax = 2.0 * b.shape->BoundingRadius() + Distance(start, b.pose.p) + margin;
		const double s = FirstSurfaceCrossing(*b.shape, b.pose, start, n, sMax);
		if (s < 0.0)
			return false;
		out = start + s * n;
		return true;
	}
	// Polygon or segment: the smallest line parameter among the edge intersections.
	const Vec2 t = Perp(n);
	const double tp = Dot(p, t);
	double best = std::numeric_limits<double>::infinity();
	const int edges = b.count == 2 ? 1 : b.count;
	for (int j = 0; j < edges; ++j)
	{
		const Vec2 u = b.vertices[j], v = b.vertices[(j + 1) % b.count];
		const double fu = Dot(u, t) - tp, fv = Dot(v, t) - tp;
		if ((fu > 0.0) == (fv > 0.0) && fu != 0.0 && fv != 0.0)
			continue;
		const double denom = fu - fv;
		const Vec2 x = denom != 0.0 ? u + (fu / denom) * (v - u) : (Dot(u, n) < Dot(v, n) ? u : v);
		best = std::min(best, Dot(x - p, n));
	}
	if (!std::isfinite(best))
		return false;
	out = p + best * n;
	return true;
}

// A non-convex particle B against A's face: its surface's lowest points along the face normal in
// each of its lobes (a heart upside down on a floor stands on both lobes). The candidates are the
// local minima of the depth below A's face plane among B's cached surface samples, over A's face;
// each is refined between its neighbours (Brent's method on the polar angle, to 1e-10 rad) and
// kept where it lies at or below the plane. The two deepest, at least twice the tolerance apart
// along the face, become the points, ids by their order along it. A single point (one lobe)
// is the lobe's lowest point; where none touches, the contact's own point stays.
int LobesOnFace(const Face& fa, const ManifoldSide& b, double tol, double radii, ManifoldPoint out[2])
{
	const Shape& shape = *b.shape;
	const SurfaceSamples& samples = shape.SamplesRef();
	const int count = samples.Count();
	const Vec2 n = fa.normal, t = Perp(n);
	auto along = [&](Vec2 x) { return Dot(x - fa.centre, t); };
	const double e0 = along(fa.ends[0]), e1 = along(fa.ends[1]);
	const double lo = std::min(e0, e1), hi = std::max(e0, e1);
	std::vector<double> depth(size_t(count), 0.0);
	for (int i = 0; i < count; ++i)
		depth[size_t(i)] = Dot(ToWorld(b.pose, samples.point[size_t(i)]) - fa.centre, n);
	ManifoldPoint best[2];
	int found = 0;
	for (int i = 0; i < count; ++i)
	{
		const double d = depth[size_t(i)];
		// (A lobe reported touches within the radii: a filter without them dropped, against a
		// chain link's 1 cm skin, whichever lobe was not the lowest, and the point hopped between
		// the lobes step after step.)
		if (!(d <= depth[size_t((i + count - 1) % count)] && d < depth[size_t((i + 1) % count)]) ||
		    d > radii + tol + 2.0 * samples.maxDeviation)
			continue;
		double a0, a1;
		samples.NeighbourAngles(i, a0, a1);
		auto height = [&](double theta) { return Dot(ToWorld(b.pose, shape.SurfacePoint(theta)) - fa.centre, n); };
		const ScalarResult m = MinimizeBrent(height, a0, a1, 1e-10, 1e-12, 60);
		const Vec2 q = ToWorld(b.pose, shape.SurfacePoint(m.x));
		const double sep = m.fx - radii, s = along(q);
		if (!(sep <= 0.0) || s < lo || s > hi)
			continue;
		// Keep the two deepest lobes; a minimum within twice the tolerance of a kept one is the
		// same lobe's (samples on either side of its bottom).
		const ManifoldPoint p{q, sep, 0};
		int same = -1;
		for (int k = 0; k < found; ++k)
			if (std::fabs(along(best[k].pointB) - s) <= 2.0 * tol)
				same = k;
		if (same >= 0)
		{
			if (sep < best[same].separation)
				best[same] = p;
		}
		else if (found < 2)
			best[found++] = p;
		else
		{
			const int shallower = best[0].separation > best[1].separation ? 0 : 1;
			if (sep < best[shallower].separation)
				best[shallower] = p;
		}
	}
	if (found == 2 && along(best[0].pointB) > along(best[1].pointB))
		std::swap(best[0], best[1]);
	for (int k = 0; k < found; ++k)
	{
		out[k] = best[k];
		out[k].id = found == 2 ? k : 0;
	}
	return found;
}

// Two particles of which one is not convex may overlap in two places (a lobe in the other's
// notch, a particle between a heart's lobes); the contact is the deepest by the scaling factor,
// and which one that is changes with every small motion. A one-point manifold then jumps between
// them step after step, the normal turning by up to 80 degrees and the warm start's impulse
// applied where the other part was: a pile of hearts churns at 0.5 m/s and never sleeps. Where a
// second part overlaps (B's surface inside A, farther than a tenth of the smaller particle from
// the contact's part; A's surface inside B where B's shows none), the manifold holds two parts:
// one normal (Box2D's manifold has one), the parts' normals weighted by their depths up to
// `full`, each point's separation the one along its own normal divided by the cosine between
// the two (what moving along the common normal must undo). The two are the contact's part and
// the deepest other, or the last manifold's two while both still overlap at least half as deep
// as the deepest part: of three parts of similar depths (a heart wedged between two lobes), the
// pair otherwise changed every other step, the normal turning by 0.5 rad. Where either part's
// normal lies more than 60 degrees from the common one, the contact's point alone. Deep parts
// (deeper than a tenth of the smaller particle) count as any other: which part is deepest by the
// scaling factor changes with small motions there, and a one-point manifold would turn its normal
// and lose its warm start with it (docs/benchmarks.md, "The pile of 3000 hearts"). `places` receives the points' own places on B (world), by which
// the next step matches its parts to these (MatchPartIds).
ContactManifold TwoPartManifold(const ContactResult& c, const ManifoldSide& a, const ManifoldSide& b, double radii, double full,
                                const ContactManifold& single, const ManifoldCache& cache, Vec2 places[2])
{
	places[0] = single.points[0].pointB;
	constexpr int kMax = 4;
	OverlapPart parts[kMax + 1]; // the contact's own part first
	const double apart = 0.1 * std::min(a.shape->BoundingRadius(), b.shape->BoundingRadius());
	parts[0] = {c.pointA, c.pointB, c.normal, single.points[0].separation + radii};
	// A part found is the contact's own where its inner surface's point (the one the search
	// found inside the other) lies within `apart` of the contact's point on that surface. (By
	// either point, a part at the tip of the outer particle, whose point on it lies as far from
	// the contact's as `apart`, counted as the contact's own one step and not the next: the
	// fallback search then named the parts with other normals, and the normal turned by 0.08 rad
	// every step.)
	auto others = [&](int count, bool innerIsB) {
		int kept = 1;
		for (int k = 1; k <= count; ++k)
		{
			const OverlapPart& p = parts[k];
			const double fromOwn = innerIsB ? Distance(p.pointB, c.pointB) : Distance(p.pointA, c.pointA);
			if (fromOwn <= apart)
				continue; // the contact's own part
			parts[kept++] = p;
		}
		return kept;
	};
	// Each part of the overlap shows both surfaces inside the other, at deepest points a part's
	// width apart: taken from either side as it came deeper, the second point hopped between
	// them (0.2 m, the normal turning 0.5 rad a step, in a settled pile of hearts). B's surface
	// inside A names the parts; A's inside B only where that shows no second part.
	// (The contact's own part, which others() drops, is not refined where it surely lies within
	// `apart` of the contact's point: OverlapSkip.)
	const OverlapSkip ownB{c.pointB, apart}, ownA{c.pointA, apart};
	int count = others(OverlapParts(*a.shape, a.pose, *b.shape, b.pose, true, parts + 1, kMax, &ownB), true);
	if (count == 1)
		count = others(OverlapParts(*b.shape, b.pose, *a.shape, a.pose, false, parts + 1, kMax, &ownA), false);
	if (count == 1)
		return single;
	int pick[2] = {0, 1}, deepest = 0;
	for (int k = 1; k < count; ++k)
	{
		if (parts[k].separation < parts[pick[1]].separation)
			pick[1] = k;
		if (parts[k].separation < parts[deepest].separation)
			deepest = k;
	}
	if (cache.partCount == 2)
	{
		// The parts nearest the last manifold's two points (B's frame), if both are still there.
		int kept[2] = {-1, -1};
		for (int j = 0; j < 2; ++j)
		{
			const Vec2 old(cache.partB[j][0], cache.partB[j][1]);
			double nearest = apart;
			for (int k = 0; k < count; ++k)
				if (Distance(ToBody(b.pose, parts[k].pointB), old) <= nearest)
				{
					nearest = Distance(ToBody(b.pose, parts[k].pointB), old);
					kept[j] = k;
				}
		}
		auto deepEnough = [&](int k) { return k >= 0 && parts[k].separation - radii <= 0.5 * (parts[deepest].separation - radii); };
		if (kept[0] != kept[1] && deepEnough(kept[0]) && deepEnough(kept[1]))
		{
			pick[0] = kept[0];
			pick[1] = kept[1];
		}
	}
	const OverlapPart& p1 = parts[pick[0]];
	const OverlapPart& p2 = parts[pick[1]];
	// The common normal leans towards each part by its depth, so that a part that starts to touch
	// (or stops) turns it from the other's normal continuously: weighted equally, a grazing part
	// coming and going turned a resting contact's normal by 0.3 rad a step. Both deeper than
	// `full` weigh the same: weighted by depths alone, two resting parts whose depths the solver
	// trades step by step turned it by 0.1-0.5 rad a step.
	const Vec2 n1 = p1.normal, n2 = p2.normal;
	const double w1 = std::clamp(-(p1.separation - radii), 0.0, full), w2 = std::clamp(-(p2.separation - radii), 0.0, full);
	const Vec2 sum = w1 + w2 > 0.0 ? w1 * n1 + w2 * n2 : n1 + n2;
	if (!(LengthSquared(sum) > 0.0))
		return single;
	const Vec2 n = Normalize(sum);
	if (!(Dot(n, n1) >= 0.5 && Dot(n, n2) >= 0.5))
		return single;
	ContactManifold m;
	m.normal = n;
	m.pointA = p1.pointA;
	const Vec2 points[2] = {p1.pointB, p2.pointB};
	const double separations[2] = {p1.separation - radii, p2.separation - radii};
	const Vec2 normals[2] = {n1, n2};
	const Vec2 t = Perp(n);
	const int first = Dot(points[0], t) <= Dot(points[1], t) ? 0 : 1;
	for (int k = 0; k < 2; ++k)
	{
		const int j = k == 0 ? first : 1 - first;
		const double sep = separations[j] / Dot(n, normals[j]);
		// B's point moved along n so that its distance from A's plane is that separation (Box2D
		// measures every point of a manifold from one plane through pointA).
		const Vec2 q = points[j] + (sep - (Dot(points[j] - m.pointA, n) - radii)) * n;
		m.points[k] = {q, sep, k};
		places[k] = points[j];
	}
	m.count = 2;
	return m;
}

// Ids for a non-convex pair's points (lobes on a face, parts of the overlap), which need not come
// in the same order or number from one step to the next: each takes the id of the nearest of the
// last manifold's points on B (B's body frame), so that Box2D carries each point's impulse with
// its own lobe or part; a point where none was (farther than a tenth of B from every one) takes
// an id none of them had, so that Box2D starts it without the impulse of a point elsewhere.
// (In a pile of hearts the second lobe or part comes and goes, and by order alone the one that
// stays swapped ids with it: the warm start then pushed where the other had been.)
// `places` are the points' places on B's surface (world): a part's manifold point is moved
// along the common normal, as far as 0.3 m where the overlap's parts lie along a curve, and
// TwoPartManifold finds the last step's parts again by their places on B, not by those points
// (a deep part's moved point can lie farther than a tenth of the particle from where the next
// step finds the part).
void MatchPartIds(ContactManifold& m, const Vec2 places[2], const ManifoldSide& b, ManifoldCache& cache)
{
	Vec2 here[2];
	for (int k = 0; k < m.count; ++k)
		here[k] = ToBody(b.pose, places[k]);
	const int before = cache.partCount;
	const double far = 0.1 * b.shape->BoundingRadius();
	auto old = [&](int j) { return Vec2(cache.partB[j][0], cache.partB[j][1]); };
	// match[k]: the old point whose id new point k takes, or −1. Two new points keep the pairing
	// with the smaller total distance.
	int match[2] = {-1, -1};
	if (m.count == 1 && before > 0)
		match[0] = before == 1 || Distance(here[0], old(0)) <= Distance(here[0], old(1)) ? 0 : 1;
	else if (m.count == 2 && before == 1)
		match[Distance(here[0], old(0)) <= Distance(here[1], old(0)) ? 0 : 1] = 0;
	else if (m.count == 2 && before == 2)
	{
		const double straight = Distance(here[0], old(0)) + Distance(here[1], old(1));
		const double crossed = Distance(here[1], old(0)) + Distance(here[0], old(1));
		match[0] = straight <= crossed ? 0 : 1;
		match[1] = 1 - match[0];
	}
	bool used[4] = {false, false, false, false};
	for (int k = 0; k < m.count; ++k)
	{
		if (match[k] >= 0 && !(Distance(here[k], old(match[k])) <= far))
			match[k] = -1;
		if (match[k] >= 0)
			used[cache.partId[match[k]]] = true;
	}
	for (int j = 0; j < before; ++j)
		used[cache.partId[j]] = true; // (an id that stopped is not given to a point elsewhere)
	for (int k = 0; k < m.count; ++k)
	{
		if (match[k] >= 0)
		{
			m.points[k].id = cache.partId[match[k]];
			continue;
		}
		int fresh = 0;
		while (used[fresh])
			++fresh;
		m.points[k].id = fresh;
		used[fresh] = true;
	}
	cache.partCount = static_cast<signed char>(m.count);
	for (int k = 0; k < m.count; ++k)
	{
		cache.partId[k] = static_cast<signed char>(m.points[k].id);
		cache.partB[k][0] = float(here[k].x);
		cache.partB[k][1] = float(here[k].y);
	}
}
} // namespace

ContactManifold BuildContactManifold(const ContactResult& c, const ManifoldSide& a, const ManifoldSide& b, double tol,
                                     double minWidth, double radii, ManifoldCache* cache)
{
	ManifoldCache scratch;
	if (!cache)
		cache = &scratch;
	// Each side's face flag holds for the next step only where this step reaches its face test.
	bool onA = cache->onA, onB = cache->onB;
	cache->onA = cache->onB = false;
	ContactManifold m;
	m.normal = c.normal;
	m.pointA = c.pointA;
	const double sep0 = Dot(c.pointB - c.pointA, c.normal) - radii;
	if (!c.Ok() || !(sep0 <= 0.0))
		return m;
	m.count = 1;
	m.points[0] = {c.pointB, sep0, 0};
	const bool twoParts = a.shape && b.shape && !a.point && !b.point && !(a.shape->IsConvex() && b.shape->IsConvex());
	// The face hysteresis (NearFacePlane) is for two faces' overlap. Where B is not convex, A's face
	// decides between B's lobes on it and the parts of the overlap, and a contact point past the
	// face's end belongs to the parts (docs/benchmarks.md, "Sleeping piles").
	if (b.shape && !b.shape->IsConvex() && !b.point)
		onA = false;
	const Face fa = SideFace(a, c.pointA, c.normal, tol, cache->faceA, cache->validA, cache->offFaceA, onA);
	cache->onA = onA;
	if (!fa.valid)
	{
		if (!twoParts)
			return m;
		Vec2 places[2];
		ContactManifold parts = TwoPartManifold(c, a, b, radii, 2.0 * tol, m, *cache, places);
		MatchPartIds(parts, places, b, *cache);
		return parts;
	}
	if (b.shape && !b.shape->IsConvex() && !b.point)
	{
		ContactManifold lobes;
		lobes.normal = fa.normal;
		lobes.pointA = fa.centre;
		lobes.count = LobesOnFace(fa, b, tol, radii, lobes.points);
		if (lobes.count < 2 && twoParts)
		{
			// One lobe on A's face, and B may overlap A elsewhere too (past the face's end, at a
			// corner): the parts of the overlap where there are two, as where the contact point lies
			// at that other part. Which of the two the scaling-factor contact finds can change from
			// step to step where they are about as deep, and the manifold then went from one lobe
			// to two parts and back, the normal turning by half a radian every step.
			Vec2 places[2];
			ContactManifold parts = TwoPartManifold(c, a, b, radii, 2.0 * tol, m, *cache, places);
			if (parts.count == 2)
			{
				MatchPartIds(parts, places, b, *cache);
				return parts;
			}
		}
		ContactManifold& out = lobes.count > 0 ? lobes : m;
		const Vec2 places[2] = {out.points[0].pointB, out.points[1].pointB};
		MatchPartIds(out, places, b, *cache);
		return out;
	}
	// (B's face gives its ends alone: A's is the reference.)
	const Face fb = SideFace(b, c.pointB, -c.normal, tol, cache->faceB, cache->validB, cache->offFaceB, onB, false);
	cache->onB = onB;
	if (!fb.valid)
		return m;
	// A's face is the reference: its normal, and its plane through its centre. The faces'
	// extents along its tangent overlap by more than the slop, or the contact is a corner's.
	const Vec2 n = fa.normal, t = Perp(n), origin = fa.centre;
	auto along = [&](Vec2 x) { return Dot(x - origin, t); };
	const double lo = std::max(std::min(along(fa.ends[0]), along(fa.ends[1])), std::min(along(fb.ends[0]), along(fb.ends[1])));
	const double hi = std::min(std::max(along(fa.ends[0]), along(fa.ends[1])), std::max(along(fb.ends[0]), along(fb.ends[1])));
	if (!(hi - lo > std::max(2.0 * tol, minWidth)))
		return m;
	// The overlap's ends: B's surface there, measured against A's face plane, as Box2D measures
	// a box's points against its reference face. (Against A's surface under each point instead,
	// which drops by up to tol towards its face's end, the separation would turn with every
	// sideways shift of B near that end: a stack of ten blocks then swayed by 5 cm, the position
	// solver feeding the turn.) Where an end lifts off (a tilted face), the other alone, with
	// its id, as Box2D's clipping keeps an incident vertex below the reference face; where both
	// lift off, the contact's own point.
	ContactManifold clipped;
	clipped.normal = n;
	clipped.pointA = origin;
	for (int k = 0; k < 2; ++k)
	{
		Vec2 q;
		if (!LowestAlong(b, origin + (k == 0 ? lo : hi) * t, n, q))
			continue;
		const double sep = Dot(q - origin, n) - radii;
		if (sep <= 0.0)
			clipped.points[clipped.count++] = {q, sep, k};
	}
	return clipped.count > 0 ? clipped : m;
}

} // namespace b2a
