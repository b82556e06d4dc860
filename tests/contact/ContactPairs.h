// b2analytic contact tests: a catalogue of shape pairs covering every family of the dispatch
// table, placed from deep overlap to well apart (shared by the symmetry and consistency tests).
#pragma once

#include "b2analytic/b2analytic.h"
#include "ContactChecks.h"

#include <string>
#include <vector>

namespace b2a::test
{

struct ShapePair
{
	std::string name;
	ShapePtr a, b;
};

/// One pair per kind of dispatch-table cell: closed form, Newton (smooth convex), the grid for
/// convex shapes with corners, the grid for hearts, and user shapes.
inline std::vector<ShapePair> FamilyPairs()
{
	return {
		{"circle-circle", MakeCircle(0.8), MakeCircle(1.3)},
		{"circle-ellipse", MakeCircle(0.8), MakeEllipse(2.0, 0.5)},
		{"ellipse-ellipse", MakeEllipse(1.5, 0.4), MakeEllipse(0.7, 1.1)},
		{"superellipse-ellipse", MakeSuperellipse(1.2, 0.8, 4.0, 6.0), MakeEllipse(1.0, 0.6)},
		{"superellipse-superellipse", MakeSuperellipse(1.0, 1.5, 2.5, 9.3), MakeSuperellipse(0.9, 0.6, 12.0, 3.0)},
		{"cornered-ellipse", MakeSuperellipse(1.0, 0.7, 1.5, 1.5), MakeEllipse(1.2, 0.5)},
		{"diamond-cornered", MakeSuperellipse(1.0, 1.0, 1.0, 1.0), MakeSuperellipse(0.8, 1.2, 1.3, 4.0)},
		{"heart-heart", MakeHeart(1.0), MakeHeart(0.5)},
		{"heart-circle", MakeHeart(1.0), MakeCircle(0.3)},
		{"heart-superellipse", MakeHeart(2.0), MakeSuperellipse(1.0, 0.5, 4.0, 4.0)},
		{"user-superellipse", MakeUserEllipse(1.3, 0.6), MakeSuperellipse(0.9, 0.9, 6.0, 6.0)},
		{"user-heart", MakeUserEllipse(0.9, 0.4), MakeHeart(0.8)},
	};
}

struct PlacedPair
{
	const ShapePair* pair;
	Pose pa, pb;
	double factor; // centre distance in units of the sum of bounding radii
};

/// Each pair at centre distances `factors` × (RA + RB) in a few directions, with generic angles.
inline std::vector<PlacedPair> Place(const std::vector<ShapePair>& pairs, const std::vector<double>& factors)
{
	std::vector<PlacedPair> out;
	const double dirs[] = {0.37, 2.1, -1.9};
	for (const ShapePair& p : pairs)
	{
		const double reach = p.a->BoundingRadius() + p.b->BoundingRadius();
		int k = 0;
		for (double f : factors)
			for (double dir : dirs)
			{
				const Pose pa(Vec2(0.3, -0.2), 0.4 + 0.3 * k);
				const Pose pb(pa.p + f * reach * Vec2(std::cos(dir), std::sin(dir)), -1.1 + 0.7 * k);
				out.push_back({&p, pa, pb, f});
				++k;
			}
	}
	return out;
}

/// True when either centre lies inside the other particle.
inline bool CentreInside(const PlacedPair& c)
{
	return c.pair->b->Level(ToBody(c.pb, c.pa.p)) <= c.pair->b->SurfaceLevel() ||
	       c.pair->a->Level(ToBody(c.pa, c.pb.p)) <= c.pair->a->SurfaceLevel();
}

/// True when ComputeContact's automatic path runs the grid for this pair.
inline bool UsesGrid(const ShapePair& p)
{
	const bool circles = p.a->Kind() == BuiltinKinds::circle && p.b->Kind() == BuiltinKinds::circle;
	return !circles && !(p.a->IsSmoothConvex() && p.b->IsSmoothConvex());
}

} // namespace b2a::test
