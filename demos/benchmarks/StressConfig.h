// b2analytic stress benchmark: random pair configurations with a known answer.
//
// Most configurations are built backwards from their answer, so that the level is a chosen
// value and the reference is exact: pick the shapes, their orientations, a level L and a contact
// normal ν; A's point of its level-L set with outward normal ν and B's point of its level set
// (L for the common level, its own level for the one-sided scale) with outward normal −ν are
// put on the same world point X. Then X, L satisfy the optimality conditions with opposed
// gradients, which for convex shapes (and, for the heart's hull points, by the separating line
// through X) characterise the answer. Rounding the centres to double moves the pair by ~1e-16
// of their coordinates; long-double Newton on the conditions (StressReference.h) restores the
// exact answer for the poses the library is given.
#pragma once

#include "StressReference.h"
#include "ReferenceRandom.h"

#include "b2analytic/b2analytic.h"

#include <cstdint>
#include <string>

namespace b2a::stress
{

/// The kinds of configuration, each with its own share of the run.
enum class Category : int
{
	general,           ///< superellipse pairs at a level from 1e-3 to 1e3
	nearTangent,       ///< |C − 1| < 1e-9
	deepOverlap,       ///< one centre inside the other (levels down to 1e-12)
	identical,         ///< both particles the same shape
	coincident,        ///< centres on the same point (same pose, or only the same position)
	randomPose,        ///< random relative poses, not built from an answer (the level is what it is)
	heartSuperellipse, ///< a heart and a superellipse, one-sided scale (grid method)
	heartHeart,        ///< two hearts, one-sided scale (grid method)
	count
};

/// Name of a category as in the output files.
inline const char* CategoryName(Category c)
{
	static const char* names[] = {"general", "near_tangent", "deep_overlap", "identical", "coincident", "random_pose",
	                              "heart_superellipse", "heart_heart"};
	return names[int(c)];
}

/// The category of configuration `index`: a fixed pattern of 100 slots, so that every run, quick
/// or full, has the same shares (general 50, near tangent 10, deep overlap 8, identical 7,
/// coincident 4, random pose 7, heart–superellipse 9, heart–heart 5 per cent).
inline Category CategoryOf(std::uint64_t index)
{
	static const int upTo[] = {50, 60, 68, 75, 79, 86, 95, 100};
	const int slot = int((index * 37) % 100); // 37 is prime to 100: the slots interleave
	for (int c = 0; c < int(Category::count); ++c)
		if (slot < upTo[c])
			return Category(c);
	return Category::general;
}

/// A shape's parameters.
struct ShapeSpec
{
	bool heart = false;            ///< heart (alpha) or superellipse (a, b, n, m)
	double a = 1.0, b = 1.0;       ///< semi-axes
	double n = 2.0, m = 2.0;       ///< exponents
	double alpha = 1.0;            ///< heart size

	/// The library's shape.
	ShapePtr Make() const { return heart ? ShapePtr(MakeHeart(alpha)) : ShapePtr(MakeSuperellipse(a, b, n, m)); }
	/// The long-double formula.
	RefShape Ref() const { return heart ? RefShape::Heart(alpha) : RefShape::Super(a, b, n, m); }
};

/// One configuration and its constructed answer.
struct Config
{
	Category category = Category::general; ///< kind
	std::uint64_t index = 0;               ///< position in the run (with the seed it reproduces the configuration)
	std::uint64_t seed = 0;                ///< the run's seed
	ShapeSpec a, b;                        ///< the shapes' parameters
	ShapePtr shapeA, shapeB;               ///< the library's shapes (the same object when identical)
	double angleA = 0.0, angleB = 0.0;     ///< orientations the poses were made from
	Pose pa, pb;                           ///< the poses given to the library
	Problem problem = Problem::common;     ///< common level, or A's one-sided scale on B
	bool constructed = false;              ///< built from an answer (else only checked by residuals)
	double targetLevel = 0.0;              ///< the level it was built for
	double normalAngle = 0.0;              ///< the normal ν it was built for
	bool corner = false;                   ///< the built point is a heart's tip (not polished)
	bool cornerA = false, cornerB = false; ///< the built point is A's tip, B's tip (hearts)
	bool tipAgainstTip = false;            ///< both built points are heart tips: the normal is not unique
	bool centreInside = false;             ///< one centre lies inside the other particle
	LevelSolution answer;                  ///< the exact answer for the double poses (when constructed)
	V built;                               ///< the built point before the centres were rounded
	double size = 1.0;                     ///< the smaller particle's bounding radius (errors are relative to it)
};

/// SplitMix64's finaliser: well-mixed bits for neighbouring inputs.
inline std::uint64_t Mix(std::uint64_t z)
{
	z += 0x632BE59BD9B4E019ull;
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
	return z ^ (z >> 31);
}

/// Random numbers for one configuration: a generator seeded from (seed, index) alone, so that a
/// configuration does not depend on the ones before it.
inline test::Random RandomFor(std::uint64_t seed, std::uint64_t index);

/// Shapes shared between configurations. Making a superellipse or a heart computes its bounding
/// radius and mass properties numerically (milliseconds), far more than a contact, so a run draws
/// its shapes from pools made on first use, as a simulation shares its shapes between particles.
/// Each pool is sorted by size, so that a shape of similar size is a neighbour.
class ShapePool
{
public:
	/// Pools of `superellipses` and `hearts` shapes drawn with `seed`.
	ShapePool(std::uint64_t seed, int superellipses, int hearts);
	/// Number of shapes of a kind.
	int Count(bool heart) const { return int(m_spec[heart].size()); }
	/// Parameters of shape i.
	const ShapeSpec& Spec(bool heart, int i) const { return m_spec[heart][i]; }
	/// The library's shape i (made on first use).
	const ShapePtr& Get(bool heart, int i)
	{
		ShapePtr& s = m_shape[heart][i];
		if (!s) s = m_spec[heart][i].Make();
		return s;
	}
	/// A random shape.
	int Any(bool heart, test::Random& r) const { return std::min(Count(heart) - 1, int(r.Uniform(0.0, Count(heart)))); }
	/// A random shape whose size is within a factor 10 of shape i's.
	int Similar(bool heart, int i, test::Random& r) const
	{
		const std::vector<double>& size = m_size[heart];
		const int lo = int(std::lower_bound(size.begin(), size.end(), size[i] / 10.0) - size.begin());
		const int hi = int(std::upper_bound(size.begin(), size.end(), size[i] * 10.0) - size.begin());
		return std::min(hi - 1, lo + int(r.Uniform(0.0, hi - lo)));
	}

private:
	std::vector<ShapeSpec> m_spec[2];
	std::vector<double> m_size[2];
	std::vector<ShapePtr> m_shape[2];
};

inline test::Random RandomFor(std::uint64_t seed, std::uint64_t index)
{
	return test::Random(Mix(seed * 0x9E3779B97F4A7C15ull + index));
}

/// A size from 1e-3 to 1e3, log-uniform, with both ends exactly 2% of the time each.
inline double RandomSize(test::Random& r)
{
	const double u = r.Uniform(0.0, 1.0);
	if (u < 0.02) return 1e-3;
	if (u < 0.04) return 1e3;
	return r.LogUniform(1e-3, 1e3);
}

/// A superellipse of bounding radius `size`: aspect ratio 1 (10%), 1000 (5%) or log-uniform in
/// between; exponents n = m = 2 (ellipses and circles, 15%), n = m = 20 (5%), equal integers
/// (20%), different integers (15%), or two reals in [2, 20] (45%).
inline ShapeSpec RandomSuperellipse(test::Random& r, double size)
{
	ShapeSpec s;
	const double u = r.Uniform(0.0, 1.0);
	const double aspect = u < 0.1 ? 1.0 : (u < 0.15 ? 1000.0 : r.LogUniform(1.0, 1000.0));
	const double v = r.Uniform(0.0, 1.0);
	auto integer = [&]() { return double(int(r.Uniform(2.0, 21.0))); };
	if (v < 0.15) s.n = s.m = 2.0;
	else if (v < 0.20) s.n = s.m = 20.0;
	else if (v < 0.40) s.n = s.m = integer();
	else if (v < 0.55) { s.n = integer(); do { s.m = integer(); } while (s.m == s.n); }
	else { s.n = r.Uniform(2.0, 20.0); s.m = r.Uniform(2.0, 20.0); }
	if (r.Uniform(0.0, 1.0) < 0.5) { s.a = size; s.b = size / aspect; }
	else { s.b = size; s.a = size / aspect; }
	return s;
}

/// A heart whose tip lies `size` from its centre (α = size²).
inline ShapeSpec RandomHeart(double size)
{
	ShapeSpec s;
	s.heart = true;
	s.alpha = size * size;
	return s;
}

inline ShapePool::ShapePool(std::uint64_t seed, int superellipses, int hearts)
{
	for (int heart = 0; heart < 2; ++heart)
	{
		const int count = std::max(1, heart ? hearts : superellipses);
		std::vector<std::pair<double, ShapeSpec>> pool;
		for (int i = 0; i < count; ++i)
		{
			// Pool shapes have their own streams, apart from the configurations' (index ≥ 2⁶²).
			test::Random r = RandomFor(seed, (std::uint64_t(1) << 62) + std::uint64_t(heart) * count + i);
			const double size = RandomSize(r);
			pool.push_back({size, heart ? RandomHeart(size) : RandomSuperellipse(r, size)});
		}
		std::sort(pool.begin(), pool.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
		for (const auto& [size, spec] : pool)
		{
			m_size[heart].push_back(size);
			m_spec[heart].push_back(spec);
		}
		m_shape[heart].resize(count);
	}
}

/// A level from 1e-3 to 1e3 (log-uniform, both ends exactly 2% of the time each).
inline double RandomLevel(test::Random& r)
{
	return RandomSize(r); // the same distribution
}

/// A level within 1e-9 of 1: exactly 1 (20%) or 1 ± 10^u, u uniform in [−16, −9.5].
inline double NearTangentLevel(test::Random& r)
{
	if (r.Uniform(0.0, 1.0) < 0.2) return 1.0;
	const double d = std::pow(10.0, r.Uniform(-16.0, -9.5));
	return r.Uniform(0.0, 1.0) < 0.5 ? 1.0 + d : 1.0 - d;
}

/// Builds the pair for shapes, orientations, level and normal: returns false when a heart's
/// support there is not unique enough (two hull points within 1e-7 of its size along ν), so
/// that the caller picks another normal.
inline bool Build(Config& c, double level, double normalAngle, V offset, bool requireUnique = true)
{
	const RefShape A = c.a.Ref(), B = c.b.Ref();
	const RefPose ra = ref::Of(Pose(Vec2(), c.angleA)), rb = ref::Of(Pose(Vec2(), c.angleB));
	const V nu{std::cos(LD(normalAngle)), std::sin(LD(normalAngle))};
	const LD levelB = c.problem == Problem::common ? LD(level) : B.Own();
	const SupportPoint sa = Support(A, level, BodyDir(ra, nu));
	const SupportPoint sb = Support(B, levelB, BodyDir(rb, V{-nu.x, -nu.y}));
	if (requireUnique && (sa.margin < 1e-7L || sb.margin < 1e-7L))
		return false;
	const V pa = offset - ref::RotateL(ra, sa.x), pb = offset - ref::RotateL(rb, sb.x);
	c.pa = Pose(Vec2(double(pa.x), double(pa.y)), c.angleA);
	c.pb = Pose(Vec2(double(pb.x), double(pb.y)), c.angleB);
	c.targetLevel = level;
	c.normalAngle = normalAngle;
	c.built = offset;
	c.corner = sa.corner || sb.corner;
	c.cornerA = sa.corner;
	c.cornerB = sb.corner;
	c.tipAgainstTip = sa.corner && sb.corner;
	c.constructed = true;
	const Posed PA{A, ref::Of(c.pa)}, PB{B, ref::Of(c.pb)};
	c.centreInside = LevelAt(PB, PA.pose.p) <= B.Own() || LevelAt(PA, PB.pose.p) <= A.Own();
	if (c.corner)
	{
		// A tip has no gradient, so the conditions do not apply there. The built answer is off by
		// the rounding of the centres (~1e-16 of their coordinates), which beside a needle turns
		// the normal by ~1e-6 rad: the one-sided scale at one tip is solved again for the rounded
		// centres (PolishTip); tip against tip keeps the built answer (its normal is not unique).
		c.answer.point = offset;
		c.answer.level = level;
		c.answer.normal = nu;
		c.answer.lastStep = ref::Len(ref::FromVec(c.pa.p) - pa) + ref::Len(ref::FromVec(c.pb.p) - pb);
		c.answer.ok = true;
		if (c.problem == Problem::scaleA && !c.tipAgainstTip)
		{
			const LevelSolution tip = PolishTip(PA, PB, sa.corner, level);
			if (tip.ok)
			{
				c.answer.point = tip.point;
				c.answer.level = tip.level;
				c.answer.normal = tip.normal;
			}
		}
	}
	else
	{
		c.answer = Polish(PA, PB, c.problem, offset, level, c.size);
	}
	return true;
}

/// A world point near the origin: the built contact point (so coordinates stay of the order of
/// the particles, and rounding of positions does not swamp the smaller one).
inline V RandomOffset(test::Random& r, double scale)
{
	return V{scale * r.Uniform(-4.0, 4.0), scale * r.Uniform(-4.0, 4.0)};
}

/// Configuration `index` of a run with `seed`, its shapes from `pool`.
inline Config MakeConfig(std::uint64_t seed, std::uint64_t index, ShapePool& pool)
{
	test::Random r = RandomFor(seed, index);
	Config c;
	c.index = index;
	c.seed = seed;
	c.category = CategoryOf(index);
	c.angleA = r.Angle();
	c.angleB = r.Angle();
	const bool hearts = c.category == Category::heartSuperellipse || c.category == Category::heartHeart;
	// A; B of independent size half of the time (size ratios up to 1e6), else within a factor 10
	// of A's (hearts against superellipses: any size); identical shapes a tenth of the heart pairs.
	const bool heartA = hearts, heartB = c.category == Category::heartHeart;
	const int ia = pool.Any(heartA, r);
	const bool similar = r.Uniform(0.0, 1.0) < 0.5;
	int ib = similar && heartA == heartB ? pool.Similar(heartB, ia, r) : pool.Any(heartB, r);
	// Coincident centres: the same pose (a third with identical shapes), or the same centre at
	// another angle.
	const double coincidence = r.Uniform(0.0, 1.0);
	if (c.category == Category::identical || (c.category == Category::coincident && coincidence < 1.0 / 3.0) ||
	    (c.category == Category::heartHeart && r.Uniform(0.0, 1.0) < 0.1))
		ib = ia;
	c.a = pool.Spec(heartA, ia);
	c.b = pool.Spec(heartB, ib);
	c.shapeA = pool.Get(heartA, ia);
	c.shapeB = pool.Get(heartB, ib);
	if (c.category == Category::heartSuperellipse && r.Uniform(0.0, 1.0) < 0.5)
	{
		std::swap(c.a, c.b);
		std::swap(c.shapeA, c.shapeB);
	}
	c.problem = hearts ? Problem::scaleA : Problem::common;
	c.size = std::min(c.shapeA->BoundingRadius(), c.shapeB->BoundingRadius());

	if (c.category == Category::coincident)
	{
		if (coincidence < 2.0 / 3.0) c.angleB = c.angleA;
		const V p = RandomOffset(r, c.size);
		c.pa = Pose(Vec2(double(p.x), double(p.y)), c.angleA);
		c.pb = Pose(c.pa.p, c.angleB);
		c.centreInside = true;
		return c;
	}
	if (c.category == Category::randomPose)
	{
		// B's centre at a distance of 0.01 to 30 times the sum of the sizes, any direction.
		const double d = (c.shapeA->BoundingRadius() + c.shapeB->BoundingRadius()) * r.LogUniform(0.01, 30.0);
		const double t = r.Angle();
		const V p = RandomOffset(r, c.size);
		c.pa = Pose(Vec2(double(p.x), double(p.y)), c.angleA);
		c.pb = Pose(c.pa.p + Vec2(d * std::cos(t), d * std::sin(t)), c.angleB);
		const Posed A{c.a.Ref(), ref::Of(c.pa)}, B{c.b.Ref(), ref::Of(c.pb)};
		c.centreInside = LevelAt(B, A.pose.p) <= B.shape.Own() || LevelAt(A, B.pose.p) <= A.shape.Own();
		return c;
	}
	auto level = [&]() {
		switch (c.category)
		{
		case Category::nearTangent: return NearTangentLevel(r);
		case Category::deepOverlap: return r.Uniform(0.0, 1.0) < 0.8 ? r.LogUniform(1e-3, 0.3) : r.LogUniform(1e-12, 1e-3);
		case Category::identical:
		{
			const double u = r.Uniform(0.0, 1.0);
			return u < 0.2 ? NearTangentLevel(r) : (u < 0.4 ? r.LogUniform(1e-6, 0.3) : RandomLevel(r));
		}
		case Category::heartSuperellipse:
		case Category::heartHeart:
		{
			const double own = c.a.heart ? c.a.alpha : 1.0;
			return own * (r.Uniform(0.0, 1.0) < 0.1 ? NearTangentLevel(r) : RandomLevel(r));
		}
		default: return RandomLevel(r);
		}
	};
	// Deep overlaps need a centre inside the other particle, hearts a unique hull point: try
	// other levels and normals (at most 40 times; the last try is kept and flagged).
	for (int attempt = 0; attempt < 40; ++attempt)
	{
		const double L = level();
		const double phi = r.Angle();
		if (!Build(c, L, phi, RandomOffset(r, c.size), attempt + 1 < 40))
			continue;
		if (c.category != Category::deepOverlap || c.centreInside)
			break;
	}
	return c;
}

} // namespace b2a::stress
