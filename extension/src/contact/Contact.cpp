// b2analytic: contact points, separation, and the shape-pair dispatch table.
#include "b2analytic/Contact.h"
#include "b2analytic/SurfaceQueries.h"

#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
// The surface point of a shape on the ray from its centre towards X (always exists).
Vec2 RadialPoint(const Shape& shape, const Pose& pose, Vec2 X)
{
	const Vec2 x = ToBody(pose, X);
	const double theta = LengthSquared(x) > 0.0 ? std::atan2(x.y, x.x) : 0.0;
	return ToWorld(pose, shape.SurfacePoint(theta));
}

// Coincident centres: no level point lies between them. Use the axis along which the overlap
// is smallest (the separating-axis depth), refined from 64 directions.
ContactResult OverlapAxisContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb)
{
	auto depth = [&](double t) {
		const Vec2 n(std::cos(t), std::sin(t));
		return Dot(WorldSupport(a, pa, n) - WorldSupport(b, pb, -n), n);
	};
	const int count = 64;
	int best = 0;
	double bestDepth = std::numeric_limits<double>::infinity();
	for (int k = 0; k < count; ++k)
	{
		const double d = depth(2.0 * kPi * k / count);
		if (d < bestDepth) { bestDepth = d; best = k; }
	}
	const double step = 2.0 * kPi / count;
	const ScalarResult m = MinimizeBrent(depth, step * (best - 1), step * (best + 1), 1e-12, 1e-14, 200);
	const double t = m.fx < bestDepth ? m.x : step * best;
	ContactResult c;
	c.status = SolveStatus::converged;
	c.method = SolveMethod::overlapAxis;
	c.normal = Vec2(std::cos(t), std::sin(t));
	c.pointA = WorldSupport(a, pa, c.normal);
	c.pointB = WorldSupport(b, pb, -c.normal);
	c.point = 0.5 * (pa.p + pb.p);
	c.separation = Dot(c.pointB - c.pointA, c.normal);
	c.touching = c.separation <= 0.0;
	c.level = 0.0;
	return c;
}

ContactResult Failed(const LevelResult& level)
{
	ContactResult c;
	c.status = SolveStatus::failed;
	c.method = level.method;
	c.failure = level.failure;
	c.iterations = level.iterations;
	return c;
}

bool Coincident(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb)
{
	return !(Distance(pa.p, pb.p) > 1e-12 * 0.5 * (a.BoundingRadius() + b.BoundingRadius()));
}
} // namespace

ContactResult ContactFromLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const LevelResult& level,
                               bool touching)
{
	ContactResult c;
	c.status = level.status;
	c.method = level.method;
	c.iterations = level.iterations;
	c.level = level.level;
	c.point = level.point;
	const Vec2 X = level.point;
	// Symmetric normal: the mean of A's outward normal and B's inward normal at X.
	const Vec2 na = Normalize(Rotate(pa.q, a.Gradient(ToBody(pa, X))));
	const Vec2 nb = Normalize(Rotate(pb.q, b.Gradient(ToBody(pb, X))));
	Vec2 n = Normalize(na - nb);
	if (LengthSquared(n) == 0.0)
		n = LengthSquared(na) > 0.0 ? na : (LengthSquared(nb) > 0.0 ? -nb : Normalize(pb.p - pa.p));
	if (LengthSquared(n) == 0.0)
		n = Vec2(1.0, 0.0);
	c.normal = n;

	// A: leave A along +n when X is inside it, else enter it along −n.
	// Beyond sMax the line has left the bounding circle for good.
	const double sMaxA = Distance(X, pa.p) + 1.01 * a.BoundingRadius();
	const bool insideA = TestPoint(a, pa, X);
	const double sa = FirstSurfaceCrossing(a, pa, X, insideA ? n : -n, sMaxA);
	c.pointA = sa >= 0.0 ? X + (insideA ? sa : -sa) * n : RadialPoint(a, pa, X);
	// B: leave B along −n when X is inside it, else enter it along +n.
	const double sMaxB = Distance(X, pb.p) + 1.01 * b.BoundingRadius();
	const bool insideB = TestPoint(b, pb, X);
	const double sb = FirstSurfaceCrossing(b, pb, X, insideB ? -n : n, sMaxB);
	c.pointB = sb >= 0.0 ? X + (insideB ? -sb : sb) * n : RadialPoint(b, pb, X);

	c.separation = Dot(c.pointB - c.pointA, n);
	if (touching && c.separation > 0.0)
		c.separation = 0.0; // tangent to rounding
	else if (!touching && !(c.separation > 0.0))
		c.separation = std::numeric_limits<double>::denorm_min(); // apart by a rounding-level gap
	c.touching = touching;
	return c;
}

ContactResult FlipContact(const ContactResult& c)
{
	ContactResult f = c;
	f.normal = -c.normal;
	f.pointA = c.pointB;
	f.pointB = c.pointA;
	return f;
}

ContactResult CircleContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions&, WarmStart*)
{
	// Closed form: the normal is the centre line, the points are the radii's ends, and the
	// separation is d − rA − rB.
	if (Coincident(a, pa, b, pb))
		return OverlapAxisContact(a, pa, b, pb);
	const double ra = a.BoundingRadius(), rb = b.BoundingRadius();
	const Vec2 d = pb.p - pa.p;
	const double dist = Length(d);
	ContactResult c;
	c.status = SolveStatus::converged;
	c.method = SolveMethod::closedForm;
	c.normal = d / dist;
	c.pointA = pa.p + ra * c.normal;
	c.pointB = pb.p - rb * c.normal;
	c.point = pa.p + (ra / (ra + rb)) * d;
	c.separation = dist - ra - rb;
	const double s = dist / (ra + rb);
	c.level = s * s;
	c.touching = c.separation <= 0.0;
	return c;
}

ContactResult ConvexContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                            WarmStart* warm)
{
	if (!a.IsSmoothConvex() || !b.IsSmoothConvex())
		return GridContact(a, pa, b, pb, options, warm);
	if (Coincident(a, pa, b, pb))
		return OverlapAxisContact(a, pa, b, pb);
	const LevelResult level = SolveCommonLevel(a, pa, b, pb, MethodChoice::automatic, options, warm);
	if (!level.Ok())
		return Failed(level);
	return ContactFromLevel(a, pa, b, pb, level, level.level <= 1.0);
}

ContactResult GridContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                          WarmStart*)
{
	if (Coincident(a, pa, b, pb))
		return OverlapAxisContact(a, pa, b, pb);
	// The grid method is one-sided (A rescaled onto B's surface). Run it both ways: the pair
	// overlaps exactly when either way finds a level at or below the own level (a particle
	// inside the other shows up as the inner one's surface inside the outer one). Choosing
	// between the two answers by a rule symmetric in A and B makes swapping A and B flip the
	// normal and swap the points exactly.
	const LevelResult ab = SolveGridScale(a, pa, b, pb, options);
	const LevelResult ba = SolveGridScale(b, pb, a, pa, options);
	if (!ab.Ok() || !ba.Ok())
		return Failed(ab.Ok() ? ba : ab);
	const bool touchAB = ab.level <= a.SurfaceLevel(), touchBA = ba.level <= b.SurfaceLevel();
	ContactResult cab = ContactFromLevel(a, pa, b, pb, ab, touchAB);
	ContactResult cba = FlipContact(ContactFromLevel(b, pb, a, pa, ba, touchBA));
	const int iterations = ab.iterations + ba.iterations;
	cab.iterations = cba.iterations = iterations;
	if (touchAB != touchBA)
		return touchAB ? cab : cba;
	// The deeper (or nearer) of the two; exact ties by the midpoint of the points, which does
	// not depend on the order of A and B.
	const double tol = 1e-12 * 0.5 * (a.BoundingRadius() + b.BoundingRadius());
	if (cab.separation < cba.separation - tol) return cab;
	if (cba.separation < cab.separation - tol) return cba;
	const Vec2 mab = 0.5 * (cab.pointA + cab.pointB), mba = 0.5 * (cba.pointA + cba.pointB);
	if (mab.x != mba.x) return mab.x < mba.x ? cab : cba;
	return mab.y <= mba.y ? cab : cba;
}

namespace
{
// The shape-pair table: generic solvers over whole families first, specialisations after.
struct DispatchTable
{
	ContactFunction cell[int(ShapeFamily::count)][int(ShapeFamily::count)];
	bool flipped[int(ShapeFamily::count)][int(ShapeFamily::count)];

	DispatchTable()
	{
		const int n = int(ShapeFamily::count);
		// The generic solvers take their pair in either order.
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j)
				SetSymmetric(ShapeFamily(i), ShapeFamily(j), &ConvexContact); // Newton or grid by the shapes' flags
		for (int i = 0; i < n; ++i)
			SetSymmetric(ShapeFamily::heart, ShapeFamily(i), &GridContact);   // never convex
		SetSymmetric(ShapeFamily::circle, ShapeFamily::circle, &CircleContact);
	}
	void SetSymmetric(ShapeFamily a, ShapeFamily b, ContactFunction f)
	{
		cell[int(a)][int(b)] = cell[int(b)][int(a)] = f;
		flipped[int(a)][int(b)] = flipped[int(b)][int(a)] = false;
	}
	// A function written for (a, b) in that order; (b, a) calls it flipped.
	void Set(ShapeFamily a, ShapeFamily b, ContactFunction f)
	{
		cell[int(a)][int(b)] = f;
		flipped[int(a)][int(b)] = false;
		if (a != b)
		{
			cell[int(b)][int(a)] = f;
			flipped[int(b)][int(a)] = true;
		}
	}
};

DispatchTable& Table()
{
	static DispatchTable table;
	return table;
}
} // namespace

void RegisterContactFunction(ShapeFamily a, ShapeFamily b, ContactFunction function)
{
	if (int(a) < 0 || int(a) >= int(ShapeFamily::count) || int(b) < 0 || int(b) >= int(ShapeFamily::count))
		throw InvalidParameter("RegisterContactFunction", "family", "must name a shape family", double(int(a)));
	if (!function)
		throw InvalidParameter("RegisterContactFunction: field 'function' is null", "function");
	Table().Set(a, b, function);
}

ContactFunction GetContactFunction(ShapeFamily a, ShapeFamily b)
{
	return Table().cell[int(a)][int(b)];
}

ContactResult ComputeContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                             const SolverOptions& options, WarmStart* warm)
{
	if (method == MethodChoice::grid)
		return GridContact(a, pa, b, pb, options, warm);
	if (method == MethodChoice::newton)
	{
		if (Coincident(a, pa, b, pb))
			return OverlapAxisContact(a, pa, b, pb);
		const LevelResult level = SolveCommonLevel(a, pa, b, pb, MethodChoice::newton, options, warm);
		if (!level.Ok())
			return Failed(level);
		return ContactFromLevel(a, pa, b, pb, level, level.level <= 1.0);
	}
	const DispatchTable& table = Table();
	const int i = int(a.Family()), j = int(b.Family());
	if (table.flipped[i][j])
	{
		// The cell was registered for (B, A): solve that way round and flip. A warm start is
		// stored in the first shape's frame, so it is not shared across the flip.
		return FlipContact(table.cell[i][j](b, pb, a, pa, options, nullptr));
	}
	return table.cell[i][j](a, pa, b, pb, options, warm);
}

} // namespace b2a
