// b2analytic: what every shape shares: radial roots, support, AABB, samples, mass by quadrature.
#include "b2analytic/Shape.h"

#include "numerics/Quadrature.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <limits>

namespace b2a
{

InvalidParameter::InvalidParameter(const std::string& what, const std::string& field, const std::string& rule, double value)
	: std::invalid_argument(what + ": field '" + field + "' " + rule + ", got " + FormatNumber(value)), m_field(field)
{
}

InvalidParameter::InvalidParameter(const std::string& message, const std::string& field)
	: std::invalid_argument(message), m_field(field)
{
}

std::string FormatNumber(double value)
{
	char buffer[64];
	std::snprintf(buffer, sizeof(buffer), "%.17g", value);
	return buffer;
}

namespace
{
struct DensePoint
{
	double theta;
	Vec2 p;
};

// The dense pass of the last shape sampled on this thread, at one resolution. Creating a fixture
// of a non-convex shape asks for two sample counts in a row (its proxy's and the default), and
// the dense pass is the costly part. The key is a serial number, not the address: a freed
// shape's address may be reused by the next one.
struct DenseCache
{
	std::uint64_t serial = 0;
	int resolution = 0;
	std::vector<DensePoint> dense;
};
thread_local DenseCache t_denseCache;

std::atomic<std::uint64_t> g_nextSerial{1};
} // namespace

Shape::Shape(ShapeKind kind, double surfaceLevel, bool convex, bool smoothConvex, double levelPower)
	: m_kind(kind), m_surfaceLevel(surfaceLevel), m_convex(convex), m_smoothConvex(smoothConvex), m_levelPower(levelPower),
	  m_serial(g_nextSerial.fetch_add(1, std::memory_order_relaxed))
{
	// The kind's solver class picks the solvers of its pairs where nobody registered one: it
	// must not promise what the shape's flags deny (Newton on a shape with corners).
	if (KindDimension(kind) != 2)
		throw InvalidParameter("shape", "kind", "must be a registered kind of dimension 2 (id)", kind.Id());
	const SolverClass solverClass = KindSolverClass(kind);
	if ((solverClass == SolverClass::smoothConvex && !smoothConvex) || (solverClass == SolverClass::convex && !convex))
		throw InvalidParameter(std::string("shape: field 'kind' (\"") + KindName(kind) + "\", solver class " +
		                           SolverClassName(solverClass) + ") claims more than the shape is (" +
		                           (convex ? "convex, not smooth" : "not convex") + ")",
		                       "kind");
}

Shape::~Shape() = default;

void Shape::AddCorner(double theta)
{
	// Kept in [−π, π), as CornerAngles promises (a user's corner may be given as any angle; one
	// remainder, as WrapAngle below, wraps even 1e300).
	theta = std::remainder(theta, 2.0 * kPi);
	m_corners.push_back(theta >= kPi ? theta - 2.0 * kPi : theta);
	std::sort(m_corners.begin(), m_corners.end());
	m_cornerDirections.clear();
	for (double c : m_corners)
		m_cornerDirections.push_back(PolarDirection(c));
	m_serial = g_nextSerial.fetch_add(1, std::memory_order_relaxed); // the dense pass depends on the corners
}

void Shape::Levels(const Vec2* x, int count, double* out) const
{
	for (int i = 0; i < count; ++i)
		out[i] = Level(x[i]);
}

void LevelBounds::LevelLowerBounds(const Vec2* centres, const double* radii, int count, double* out) const
{
	for (int i = 0; i < count; ++i)
		out[i] = LevelLowerBound(centres[i], radii[i]);
}

double Shape::RadiusAt(Vec2 u, double level) const
{
	// Generic radial root of λ(t·u) = level. λ increases along the ray (star-shaped), so
	// bracket [lo, hi] by doubling from a length scale and finish with Brent's method.
	auto phi = [&](double t) { return Level(t * u) - level; };
	const double f0 = phi(0.0);
	if (!(f0 < 0.0))
		return 0.0; // the level set does not contain the origin: empty along every ray
	double lo = 0.0, flo = f0;
	double hi = m_boundingRadius > 0.0 ? m_boundingRadius : LengthHint();
	double fhi = phi(hi);
	// Grow by a factor that squares each time (2, 4, 16, ... up to 1e8): a surface far out (a
	// level far above the own one) is bracketed in tens of steps, and the root search below
	// narrows the wide bracket on a logarithmic scale.
	double factor = 2.0;
	for (int i = 0; i < 2000 && !(fhi >= 0.0); ++i)
	{
		if (std::isnan(fhi) || fhi == -std::numeric_limits<double>::infinity())
			return std::numeric_limits<double>::quiet_NaN(); // no surface along this ray
		lo = hi;
		flo = fhi;
		hi *= factor;
		factor = std::min(factor * factor, 1e8);
		fhi = phi(hi);
	}
	if (!(fhi >= 0.0))
		return std::numeric_limits<double>::quiet_NaN();
	if (!std::isfinite(fhi))
	{
		// Bisect on the sign until the upper end is finite, so Brent gets a finite bracket.
		for (int i = 0; i < 200 && !std::isfinite(fhi); ++i)
		{
			const double mid = 0.5 * (lo + hi);
			const double fm = phi(mid);
			if (fm < 0.0) { lo = mid; flo = fm; }
			else { hi = mid; fhi = fm; }
		}
	}
	const ScalarResult r = FindRootScaleFree(phi, lo, hi, flo, fhi, 300);
	return r.x;
}

Vec2 Shape::SurfacePoint(double theta, double level) const
{
	const Vec2 u = PolarDirection(theta);
	return RadiusAt(u, level) * u;
}

Vec2 Shape::Support(Vec2 d) const
{
	// Support of the convex hull: the sample farthest along d, then the maximum of
	// f(θ) = d·x(θ) between its neighbours.
	const SurfaceSamples& samples = SamplesRef();
	const int n = samples.Count();
	int best = 0;
	double bestValue = -std::numeric_limits<double>::infinity();
	for (int i = 0; i < n; ++i)
	{
		const double v = Dot(d, samples.point[i]);
		if (v > bestValue) { bestValue = v; best = i; }
	}
	double lo, hi;
	samples.NeighbourAngles(best, lo, hi);
	const double L = m_surfaceLevel;
	// Where f's slope changes sign between the neighbours, its root is the maximum, found by a
	// bracketed root search to 1e-10 rad in about six surface points with their gradients (the
	// minimisation below, which needs no slope, takes about fifty to reach rounding, and a
	// heart's support 2.4 times as long). f is flat at its maximum: the value is exact to
	// rounding, and the point to 1e-10 of the size. On
	// x = r·u, u = (cos θ, sin θ), the level's gradient g is normal to x' = r'·u + r·u⊥, so
	// r' = −r (g·u⊥)/(g·u) and f' = r'·(d·u) + r·(d·u⊥). At a corner (a heart's tip) the slope
	// jumps there, and the search closes on the corner.
	auto slope = [&](double t) {
		const Vec2 u(std::cos(t), std::sin(t)), w = Perp(u);
		const double r = RadiusAt(u, L);
		const Vec2 g = Gradient(r * u);
		const double gu = Dot(g, u);
		return gu > 0.0 ? -r * Dot(g, w) / gu * Dot(d, u) + r * Dot(d, w) : std::numeric_limits<double>::quiet_NaN();
	};
	const double sLo = slope(lo), sHi = slope(hi);
	if (sLo > 0.0 && sHi < 0.0 && std::isfinite(sLo) && std::isfinite(sHi))
	{
		const ScalarResult r = FindRootBrent(slope, lo, hi, sLo, sHi, 1e-10, 100);
		const Vec2 x = SurfacePoint(r.x, L);
		if (Dot(d, x) >= bestValue)
			return x;
	}
	auto negProj = [&](double t) { return -Dot(d, SurfacePoint(t, L)); };
	const ScalarResult r = MinimizeBrent(negProj, lo, hi, 1e-15, 1e-15, 200);
	if (-r.fx >= bestValue)
		return SurfacePoint(r.x, L);
	return samples.point[best];
}

Box Shape::ComputeAABB(const Pose& pose) const
{
	// World extreme along ±x and ±y = body support along the world axes pulled back.
	const Vec2 ex = InvRotate(pose.q, Vec2(1.0, 0.0));
	const Vec2 ey = InvRotate(pose.q, Vec2(0.0, 1.0));
	Box b;
	b.upper.x = ToWorld(pose, Support(ex)).x;
	b.lower.x = ToWorld(pose, Support(-ex)).x;
	b.upper.y = ToWorld(pose, Support(ey)).y;
	b.lower.y = ToWorld(pose, Support(-ey)).y;
	return b;
}

namespace
{
// Angle of the vector b relative to a, in [0, π].
double TurnAngle(Vec2 a, Vec2 b)
{
	return std::fabs(std::atan2(Cross(a, b), Dot(a, b)));
}

double WrapAngle(double t)
{
	// One remainder, not a loop of 2π steps: a user's corner angle of 1e300 is finite, and
	// subtracting 2π from it changes nothing (the loop never ended; found by the solver fuzzer).
	t = std::remainder(t, 2.0 * kPi); // in [−π, π]
	return t >= kPi ? t - 2.0 * kPi : t;
}

} // namespace

namespace
{
// The dense pass: SurfacePoint at angles refined until chords are short and straight, at a
// resolution of 8 chords and 4 turns of the chord direction per sample of a given count: 2048
// and 1024 per revolution for the default 256 samples (about 3000 surface points), 256 and 128
// for 32 (a proxy's 7 need no finer polyline to be spread along).
void DenseSamples(const Shape& shape, int resolution, std::vector<DensePoint>& dense)
{
	const double L = shape.SurfaceLevel();
	std::vector<double> start;
	const int initial = 64;
	for (int i = 0; i < initial; ++i)
		start.push_back(-kPi + 2.0 * kPi * i / initial);
	for (double c : shape.CornerAngles())
		start.push_back(WrapAngle(c));
	std::sort(start.begin(), start.end());
	start.erase(std::unique(start.begin(), start.end()), start.end());

	double scale = 0.0;
	std::vector<Vec2> startPoints;
	for (double t : start)
	{
		startPoints.push_back(shape.SurfacePoint(t, L));
		scale = std::max(scale, Length(startPoints.back()));
	}
	const double hMax = scale * 2.0 * kPi / (8.0 * resolution);
	const double tanTurnMax = std::tan(2.0 * kPi / (4.0 * resolution));
	struct Task { double t0; Vec2 p0; double t1; Vec2 p1; int depth; };
	std::vector<Task> stack;
	for (size_t i = 0; i < start.size(); ++i)
	{
		const size_t j = (i + 1) % start.size();
		const double t1 = j == 0 ? start[0] + 2.0 * kPi : start[j];
		// Push in reverse order of processing so that output stays ordered by angle.
		stack.clear();
		stack.push_back({start[i], startPoints[i], t1, startPoints[j], 0});
		while (!stack.empty())
		{
			const Task task = stack.back();
			stack.pop_back();
			const double tm = 0.5 * (task.t0 + task.t1);
			const Vec2 pm = shape.SurfacePoint(tm, L);
			const bool longChord = Distance(task.p0, task.p1) > hMax;
			// Turned by more than turnMax: a test on the cross and dot products, without atan2.
			const Vec2 in = pm - task.p0, out = task.p1 - pm;
			const double along = Dot(in, out), across = std::fabs(Cross(in, out));
			// (Turned back, along < 0, counts; a zero or non-finite chord does not.)
			const bool turning = along < 0.0 || across > tanTurnMax * along;
			if ((longChord || turning) && task.depth < 40)
			{
				stack.push_back({tm, pm, task.t1, task.p1, task.depth + 1});
				stack.push_back({task.t0, task.p0, tm, pm, task.depth + 1});
			}
			else
			{
				dense.push_back({task.t0, task.p0});
			}
		}
	}
}
} // namespace

const SurfaceSamples& Shape::SamplesRef(int count) const
{
	// Entries of m_samples are never removed, so a pointer to one stays valid with the shape.
	// (A count whose samples number other than the count asked for always takes the lock.)
	const SurfaceSamples* last = m_lastSamples.load(std::memory_order_acquire);
	if (last && last->Count() == count)
		return *last;
	const std::shared_ptr<const SurfaceSamples> samples = Samples(count);
	m_lastSamples.store(samples.get(), std::memory_order_release);
	return *samples;
}

std::shared_ptr<const SurfaceSamples> Shape::Samples(int count) const
{
	if (count < 3)
		throw InvalidParameter("surface samples", "count", "must be >= 3", count);
	std::lock_guard<std::mutex> lock(m_sampleMutex);
	for (const auto& entry : m_samples)
		if (entry.first == count)
			return entry.second;

	const double L = m_surfaceLevel;
	// 1. Dense adaptive polar sampling: split an angle interval while its chord is long or
	//    the chord direction turns, so thin tips and cusps are resolved.
	//    Below 32 samples (a proxy's 7) a pass for 32, which needs no finer polyline; from 32 up
	//    the default's, whose resolution the grid method's samples are spread along.
	const int resolution = count < 32 ? 32 : kDefaultSampleCount;
	DenseCache& cache = t_denseCache;
	if (cache.serial != m_serial || cache.resolution != resolution)
	{
		cache.serial = 0; // stays invalid if the pass throws
		cache.dense.clear();
		DenseSamples(*this, resolution, cache.dense);
		cache.serial = m_serial;
		cache.resolution = resolution;
	}
	// A copy: SurfacePoint below runs user code (a UserShape's function), which may sample
	// another shape on this thread.
	const std::vector<DensePoint> dense = cache.dense;
	const int nd = int(dense.size());
	for (const DensePoint& d : dense)
		if (!IsFinite(d.p))
			throw InvalidParameter(Describe() + ": no finite surface point at polar angle " + FormatNumber(d.theta) +
			                           " (field 'function' must describe a bounded, star-shaped particle)",
			                       "function");

	// 2. Equidistribute the combined measure: half arc length, half turning.
	std::vector<double> len(nd), turn(nd);
	double perimeter = 0.0, totalTurn = 0.0;
	for (int i = 0; i < nd; ++i)
	{
		len[i] = Distance(dense[i].p, dense[(i + 1) % nd].p);
		perimeter += len[i];
	}
	for (int i = 0; i < nd; ++i)
	{
		const Vec2 in = dense[i].p - dense[(i + nd - 1) % nd].p;
		const Vec2 out = dense[(i + 1) % nd].p - dense[i].p;
		turn[i] = TurnAngle(in, out);
		totalTurn += turn[i];
	}
	std::vector<double> weight(nd), cumulative(nd + 1, 0.0);
	for (int i = 0; i < nd; ++i)
	{
		weight[i] = len[i] / perimeter + 0.5 * (turn[i] + turn[(i + 1) % nd]) / totalTurn;
		cumulative[i + 1] = cumulative[i] + weight[i];
	}
	auto out = std::make_shared<SurfaceSamples>();
	out->level = L;
	int seg = 0;
	for (int k = 0; k < count; ++k)
	{
		const double target = (k + 0.5) / count * cumulative[nd];
		while (seg + 1 < nd && cumulative[seg + 1] < target) ++seg;
		const double frac = weight[seg] > 0.0 ? (target - cumulative[seg]) / weight[seg] : 0.0;
		const double t0 = dense[seg].theta;
		double t1 = dense[(seg + 1) % nd].theta;
		if (t1 <= t0) t1 += 2.0 * kPi;
		out->angle.push_back(WrapAngle(t0 + frac * (t1 - t0)));
	}
	// Put each corner exactly on its nearest sample, so that cusps are candidates themselves.
	for (double c : m_corners)
	{
		const double wc = WrapAngle(c);
		int nearest = 0;
		double bestGap = 1e300;
		for (int k = 0; k < count; ++k)
		{
			const double gap = std::fabs(WrapAngle(out->angle[k] - wc));
			if (gap < bestGap) { bestGap = gap; nearest = k; }
		}
		out->angle[nearest] = wc;
	}
	std::sort(out->angle.begin(), out->angle.end());
	out->angle.erase(std::unique(out->angle.begin(), out->angle.end()), out->angle.end());
	for (double t : out->angle)
		out->point.push_back(SurfacePoint(t, L));

	// 3. Spacing and the measured deviation of the true curve from the sample polygon.
	const int n = out->Count();
	std::vector<double>& deviation = out->arcDeviation; // of arc k → k + 1
	deviation.assign(size_t(n), 0.0);
	for (int k = 0; k < n; ++k)
	{
		const int j = (k + 1) % n;
		out->maxSpacing = std::max(out->maxSpacing, Distance(out->point[k], out->point[j]));
		double t0 = out->angle[k], t1 = out->angle[j];
		if (t1 <= t0) t1 += 2.0 * kPi;
		for (int q = 1; q < 4; ++q)
		{
			const Vec2 mid = SurfacePoint(t0 + (t1 - t0) * q / 4.0, L);
			deviation[size_t(k)] = std::max(deviation[size_t(k)], DistanceToSegment(mid, out->point[k], out->point[j]));
		}
		out->maxDeviation = std::max(out->maxDeviation, deviation[size_t(k)]);
	}
	m_samples.emplace_back(count, out);
	return out;
}

void Shape::Finalize(double boundingRadius, const MassProperties* mass)
{
	const double L = m_surfaceLevel;
	m_centreLevel = Level(Vec2());
	m_cornerPoints.clear();
	for (const Vec2 u : m_cornerDirections)
		m_cornerPoints.push_back(RadiusAt(u, L) * u);
	if (boundingRadius > 0.0)
	{
		m_boundingRadius = boundingRadius;
	}
	else
	{
		// Largest sample radius, refined between its neighbours.
		const auto s = Samples();
		const int n = s->Count();
		int best = 0;
		for (int i = 1; i < n; ++i)
			if (Length(s->point[i]) > Length(s->point[best])) best = i;
		double lo, hi;
		s->NeighbourAngles(best, lo, hi);
		auto negR = [&](double t) { return -Length(SurfacePoint(t, L)); };
		const ScalarResult r = MinimizeBrent(negR, lo, hi, 1e-15, 1e-15, 200);
		m_boundingRadius = std::max(-r.fx, Length(s->point[best]));
	}
	if (mass)
	{
		m_mass = *mass;
		return;
	}
	// Polar quadrature over the star-shaped region r ≤ R(θ):
	//   A = ∫R²/2, ∫x dA = ∫R³cosθ/3, ∫x² dA = ∫R⁴cos²θ/4, ...
	std::vector<double> breaks;
	for (int i = 0; i <= 16; ++i)
		breaks.push_back(-kPi + 2.0 * kPi * i / 16);
	for (double c : m_corners)
		breaks.push_back(WrapAngle(c));
	std::sort(breaks.begin(), breaks.end());
	breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
	auto integrand = [&](double t) {
		const double c = std::cos(t), s = std::sin(t);
		const double R = RadiusAt(Vec2(c, s), L);
		const double R2 = R * R, R3 = R2 * R, R4 = R2 * R2;
		return std::array<double, 6>{R2 / 2.0, R3 * c / 3.0, R3 * s / 3.0, R4 * c * c / 4.0, R4 * s * s / 4.0, R4 * c * s / 4.0};
	};
	const auto q = IntegrateAdaptive<6>(integrand, breaks, 1e-14, 20000);
	MassProperties mp;
	mp.area = q.value[0];
	mp.centroid = Vec2(q.value[1], q.value[2]) / mp.area;
	mp.Iyy = q.value[3] - mp.area * mp.centroid.x * mp.centroid.x;
	mp.Ixx = q.value[4] - mp.area * mp.centroid.y * mp.centroid.y;
	mp.Ixy = q.value[5] - mp.area * mp.centroid.x * mp.centroid.y;
	mp.polarMoment = mp.Ixx + mp.Iyy;
	m_mass = mp;
}

} // namespace b2a
