// b2analytic: heart-shaped particle.
#include "b2analytic/HeartShape.h"

#include "numerics/Powers.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{
namespace
{
// A monotone stand-in for the polar angle of v, in [0, 4) over one turn from the +x axis
// (the "diamond angle"): binary searches over directions need no arctangent.
inline double PseudoAngle(Vec2 v)
{
	if (v.y >= 0.0)
		return v.x >= 0.0 ? v.y / (v.x + v.y) : 1.0 - v.x / (v.y - v.x);
	return v.x < 0.0 ? 2.0 - v.y / (-v.x - v.y) : 3.0 + v.x / (v.x - v.y);
}
} // namespace

HeartShape::HeartShape(double alpha) : Shape(BuiltinKinds::nonConvex, alpha, false, false, 1.0), m_alpha(alpha)
{
	if (!std::isfinite(alpha) || !(alpha > 0.0))
		throw InvalidParameter("heart", "alpha", "must be finite and > 0", alpha);
	m_alphaSixth = std::pow(alpha, 1.0 / 6.0);
	SetDerivativesCheap();
	SetSupportBoundsCheap(); // (the surface sample farthest along the direction)
	AddCorner(0.5 * kPi);  // notch
	AddCorner(-0.5 * kPi); // tip
	Finalize(-1.0, nullptr);
	// The hull's tangent from the tip (0, −√α) to the right lobe: the largest angle from the
	// vertical of x − tip over the right half of the outline (x > 0), between the tip's cusp
	// (vertical tangent) and the notch (vertical again), refined about the best of 64 angles.
	const double tipY = -std::sqrt(alpha);
	auto negAngle = [&](double t) {
		const Vec2 x = SurfacePoint(t, alpha);
		return -std::atan2(x.x, x.y - tipY);
	};
	const int n = 64;
	double best = 0.0, bestValue = std::numeric_limits<double>::infinity();
	for (int i = 1; i < n; ++i)
	{
		const double t = -0.5 * kPi + kPi * i / n, v = negAngle(t);
		if (v < bestValue) { bestValue = v; best = t; }
	}
	const ScalarResult r = MinimizeBrent(negAngle, best - kPi / n, best + kPi / n, 1e-15, 1e-15, 200);
	const double phi = -std::min(r.fx, bestValue);
	m_tipSin = std::sin(phi);
	m_tipCos = std::cos(phi);
	// The samples' convex hull (Andrew's monotone chain, collinear points dropped).
	const SurfaceSamples& samples = SamplesRef();
	std::vector<int> order(size_t(samples.Count()));
	for (size_t i = 0; i < order.size(); ++i)
		order[i] = int(i);
	std::sort(order.begin(), order.end(), [&](int a, int b) {
		const Vec2 p = samples.point[size_t(a)], q = samples.point[size_t(b)];
		return p.x < q.x || (p.x == q.x && p.y < q.y);
	});
	std::vector<int> hull(2 * order.size());
	size_t k = 0;
	auto turnsLeft = [&](int a, int b, int c) {
		return Cross(samples.point[size_t(b)] - samples.point[size_t(a)], samples.point[size_t(c)] - samples.point[size_t(a)]) > 0.0;
	};
	for (size_t i = 0; i < order.size(); ++i)
	{
		while (k >= 2 && !turnsLeft(hull[k - 2], hull[k - 1], order[i]))
			--k;
		hull[k++] = order[i];
	}
	for (size_t i = order.size() - 1, lower = k + 1; i-- > 0;)
	{
		while (k >= lower && !turnsLeft(hull[k - 2], hull[k - 1], order[i]))
			--k;
		hull[k++] = order[i];
	}
	hull.resize(k - 1);
	m_hull = hull;
	for (size_t i = 0; i < m_hull.size(); ++i)
	{
		const Vec2 e = samples.point[size_t(m_hull[(i + 1) % m_hull.size()])] - samples.point[size_t(m_hull[i])];
		double a = PseudoAngle(Vec2(e.y, -e.x));
		while (!m_hullNormal.empty() && a < m_hullNormal.back())
			a += 4.0;
		m_hullNormal.push_back(a);
	}
}

int HeartShape::BestSample(Vec2 d) const
{
	double a = PseudoAngle(d);
	if (a < m_hullNormal.front())
		a += 4.0;
	const size_t j = size_t(std::upper_bound(m_hullNormal.begin(), m_hullNormal.end(), a) - m_hullNormal.begin());
	return m_hull[j % m_hull.size()];
}

std::string HeartShape::Describe() const
{
	return "heart(alpha=" + FormatNumber(m_alpha) + ")";
}

double HeartShape::LengthHint() const
{
	return 1.5 * std::sqrt(m_alpha);
}

namespace
{
// (r² − α)³ = x² y³  ⇔  α = r² − cbrt(x² y³), and (r² − α)³ is decreasing in α.
inline double HeartLevel(Vec2 x) { return x.x * x.x + x.y * x.y - CubeRoot(x.x * x.x) * x.y; }

// The Hessian [[2 + a, ∓e], [∓e, 2]] of the level off the axis, a = (2/9)|x|^{−4/3} y and
// e = (2/3)|x|^{−1/3}, has eigenvalues 2 + a/2 ± √(a²/4 + e²), which lie within
// 2 + min(a, 0) − e and 2 + max(a, 0) + e. Over the disc of radius ρ about c, |x| ≥ |cx| − ρ
// and |y − cy| ≤ ρ, so with k an upper bound of (|cx| − ρ)^{−1/3} they lie within
//   2 + (2/9) min(cy − ρ, 0) k⁴ − (2/3) k  and  2 + (2/9) max(cy + ρ, 0) k⁴ + (2/3) k.
// For t = ρ/|cx| ≤ 1/2, (1 − t)^{−1/3} lies below its chord 1 + 2(2^{1/3} − 1)t ≤ 1 + 0.52t
// (it is convex), so k = |cx|^{−1/3}(1 + 0.52t): one cube root, at the centre, by
// RoughCubeRootWithInverse (2e-8), and k taken 1e-6 high, fifty times that.
struct DiscCubeRoots
{
	double root;    // |cx|^{1/3}, within 2e-8
	double inverse; // |cx|^{−1/3}, within 2e-8
	double k;       // ≥ (|cx| − ρ)^{−1/3}
};
// False where the disc's centre lies within 2ρ of the axis, |cx| < 2ρ (or |cx| is outside the
// table's range).
inline bool CubeRootsOverDisc(Vec2 centre, double radius, DiscCubeRoots& r)
{
	const double ax = std::fabs(centre.x);
	if (!(ax >= kCubeRootLowest && ax <= kCubeRootHighest))
		return false;
	r.root = RoughCubeRootWithInverse(ax, r.inverse);
	const double t = radius * ((r.inverse * r.inverse) * r.inverse); // ρ/|cx|
	if (!(t <= 0.5))
		return false;
	r.k = (r.inverse * (1.0 + 0.52 * t)) * (1.0 + 1e-6);
	return true;
}

// The terms of the eigenvalue bounds above over the disc of radius ρ about c, from k:
// the least eigenvalue is at least 2 + down − e and the greatest at most 2 + up + e, with
// down = (2/9) min(cy − ρ, 0) k⁴, up = (2/9) max(cy + ρ, 0) k⁴ and e = (2/3) k. (Taylor's box
// bound and the curvature bounds share them.)
struct EigenvalueTerms
{
	double down, up, e;
};
inline EigenvalueTerms EigenvalueTermsOverDisc(Vec2 centre, double radius, double k)
{
	const double k2 = k * k, k4 = k2 * k2;
	return {(2.0 / 9.0) * std::min(centre.y - radius, 0.0) * k4, (2.0 / 9.0) * std::max(centre.y + radius, 0.0) * k4,
	        (2.0 / 3.0) * k};
}
} // namespace

double HeartShape::Level(Vec2 x) const
{
	return HeartLevel(x);
}

void HeartShape::Levels(const Vec2* x, int count, double* out) const
{
	int i = 0;
#if defined(B2A_SSE2_PAIRS)
	// Two points at a time: the operations of HeartLevel and CubeRoot, in the same order, on
	// the two lanes of SSE2 registers, so that each lane's value is Level's bit for bit (the
	// cube root, a table cell and a polynomial, is the level's cost, and its arithmetic runs
	// two lanes at a time). Pairs with a cube root outside CubeRoot's main range (0, NaN,
	// infinities) take the scalar path. (Four AVX2 lanes, here and in LevelLowerBounds, would
	// give the same bits with gathered table cells, but a contact waits on other work, not on
	// these evaluations: faster runs alone do not make a faster contact.)
	static_assert(sizeof(Vec2) == 2 * sizeof(double), "Vec2 is two packed doubles");
	const __m128d lowest = _mm_set1_pd(kCubeRootLowest), highest = _mm_set1_pd(kCubeRootHighest);
	for (; i + 2 <= count; i += 2)
	{
		const __m128d p0 = _mm_loadu_pd(&x[i].x), p1 = _mm_loadu_pd(&x[i + 1].x);
		const __m128d px = _mm_unpacklo_pd(p0, p1), py = _mm_unpackhi_pd(p0, p1);
		const __m128d ax = _mm_mul_pd(px, px);
		if (_mm_movemask_pd(_mm_and_pd(_mm_cmpge_pd(ax, lowest), _mm_cmple_pd(ax, highest))) != 3)
		{
			out[i] = HeartLevel(x[i]);
			out[i + 1] = HeartLevel(x[i + 1]);
			continue;
		}
		const __m128d c = CubeRootPair(ax);
		_mm_storeu_pd(out + i, _mm_sub_pd(_mm_add_pd(ax, _mm_mul_pd(py, py)), _mm_mul_pd(c, py)));
	}
#endif
	for (; i < count; ++i)
		out[i] = HeartLevel(x[i]);
}

LevelDerivatives HeartShape::Derivatives(Vec2 x) const
{
	// α(x, y) = x² + y² − |x|^{2/3} y:
	//   ∂x = 2x − (2/3) sgn(x) |x|^{−1/3} y,   ∂y = 2y − |x|^{2/3},
	//   ∂xx = 2 + (2/9) |x|^{−4/3} y,  ∂xy = −(2/3) sgn(x) |x|^{−1/3},  ∂yy = 2.
	// (|x|^{−1/3} from the cube root's table, with no division: CubeRootWithInverse.)
	LevelDerivatives d;
	const double ax = std::fabs(x.x);
	double ic;                                    // |x|^{−1/3}
	const double c = CubeRootWithInverse(ax, ic); // |x|^{1/3}
	d.value = x.x * x.x + x.y * x.y - c * c * x.y;
	d.hessian.yy = 2.0;
	d.gradient.y = 2.0 * x.y - c * c;
	if (ax == 0.0)
	{
		d.gradient.x = 0.0;
		d.hessian.xx = 2.0;
		d.hessian.xy = 0.0;
		return d;
	}
	const double sic = x.x > 0.0 ? ic : -ic; // sgn(x) |x|^{−1/3}
	d.gradient.x = 2.0 * x.x - ((2.0 / 3.0) * sic) * x.y;
	d.hessian.xx = 2.0 + ((2.0 / 9.0) * x.y) * ((ic * ic) * (ic * ic));
	d.hessian.xy = -(2.0 / 3.0) * sic;
	return d;
}

double HeartShape::LevelLowerBound(Vec2 centre, double radius) const
{
	// Over |x − c| ≤ ρ: |x|² ≥ (|c| − ρ)₊², the exact least |x|² on the disc, taken a rounding
	// lower (1e-15 of |c|) so that it stays a bound. (Per component, dx² + dy² with
	// d = (|c| − ρ)₊ per axis, is looser by up to 2ρ(|cx| + |cy| − |c|), and the grid would
	// scan more runs.) The cusp term −|x|^{2/3} y ≥
	// −(|cx| + ρ)^{2/3} (cy + ρ) where the disc reaches y > 0, and where it lies below the x
	// axis it adds at least dx^{2/3} |cy + ρ| with dx = (|cx| − ρ)₊.
	// (The cube root by its bounds: the upper one where the term is subtracted, the lower one
	// where it is added.)
	const double dx = std::max(std::fabs(centre.x) - radius, 0.0);
	const double near = std::max(Length(centre) * (1.0 - 1e-15) - radius, 0.0);
	const double top = centre.y + radius;
	const double reach = top > 0.0 ? std::fabs(centre.x) + radius : dx;
	double lower, upper;
	CubeRootBounds(reach * reach, lower, upper);
	return near * near - (top > 0.0 ? upper : lower) * top;
}

void HeartShape::LevelLowerBounds(const Vec2* centres, const double* radii, int count, double* out) const
{
	int i = 0;
#if defined(B2A_SSE2_PAIRS)
	// LevelLowerBound's operations in its order on two lanes (as Levels does the level's). A
	// pair whose |c|² or cube-root argument lies outside the ranges where Length takes the
	// square root (the same bounds, exclusive) and CubeRootBounds iterates (or is not finite)
	// takes the scalar path; a zero
	// argument (a disc on the axis: exact bounds 0) is iterated on 1 and its bound zeroed.
	const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
	const __m128d lowest = _mm_set1_pd(kCubeRootLowest), highest = _mm_set1_pd(kCubeRootHighest);
	const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
	for (; i + 2 <= count; i += 2)
	{
		const __m128d c0 = _mm_loadu_pd(&centres[i].x), c1 = _mm_loadu_pd(&centres[i + 1].x);
		const __m128d cx = _mm_unpacklo_pd(c0, c1), cy = _mm_unpackhi_pd(c0, c1);
		const __m128d r = _mm_loadu_pd(radii + i);
		const __m128d acx = _mm_and_pd(cx, magnitude);
		const __m128d dx = _mm_max_pd(zero, _mm_sub_pd(acx, r)); // std::max(a, 0): NaN stays
		const __m128d s = _mm_add_pd(_mm_mul_pd(cx, cx), _mm_mul_pd(cy, cy));
		const __m128d near = _mm_max_pd(zero, _mm_sub_pd(_mm_mul_pd(_mm_sqrt_pd(s), _mm_set1_pd(1.0 - 1e-15)), r));
		const __m128d top = _mm_add_pd(cy, r);
		const __m128d up = _mm_cmpgt_pd(top, zero);
		const __m128d reach = _mm_or_pd(_mm_and_pd(up, _mm_add_pd(acx, r)), _mm_andnot_pd(up, dx));
		const __m128d x = _mm_mul_pd(reach, reach);
		const __m128d flat = _mm_cmpeq_pd(x, zero);
		const __m128d lengthOk = _mm_and_pd(_mm_cmpgt_pd(s, lowest), _mm_cmplt_pd(s, highest));
		const __m128d rootOk = _mm_or_pd(flat, _mm_and_pd(_mm_cmpge_pd(x, lowest), _mm_cmple_pd(x, highest)));
		if (_mm_movemask_pd(_mm_and_pd(lengthOk, rootOk)) != 3)
		{
			out[i] = LevelLowerBound(centres[i], radii[i]);
			out[i + 1] = LevelLowerBound(centres[i + 1], radii[i + 1]);
			continue;
		}
		const __m128d t = _mm_or_pd(_mm_and_pd(flat, one), _mm_andnot_pd(flat, x));
		const __m128d y = CubeRootBoundsPair(t);
		const __m128d upper = _mm_mul_pd(y, _mm_set1_pd(kCubeRootUpperMargin)), lower = _mm_mul_pd(y, _mm_set1_pd(kCubeRootLowerMargin));
		const __m128d side = _mm_andnot_pd(flat, _mm_or_pd(_mm_and_pd(up, upper), _mm_andnot_pd(up, lower)));
		_mm_storeu_pd(out + i, _mm_sub_pd(_mm_mul_pd(near, near), _mm_mul_pd(side, top)));
	}
#endif
	for (; i < count; ++i)
		out[i] = LevelLowerBound(centres[i], radii[i]);
}

double HeartShape::TightLevelLowerBound(const OrientedBox& box) const
{
	// Taylor's theorem about the box's centre c, with integral remainder:
	//   λ(c + d) ≥ λ(c) + ∇λ(c)·d + (m/2)|d|²,
	// m a lower bound of the Hessian's least eigenvalue over the box, which must keep off the
	// axis, where λ is not smooth: CubeRootsOverDisc's, over the disc of radius
	// ρ = √(l² + w²) around the box (l, w its half-length and half-width),
	//   m = 2 + (2/9) min(cy − ρ, 0) k⁴ − (2/3) k.
	// The box is a product of two intervals, d = s·u + r·v (u along it, v across, |s| ≤ l,
	// |r| ≤ w), and |d|² = s² + r², so the least of ∇λ·d + (m/2)|d|² is the sum of each
	// interval's least of g s + (m/2) s²: −|g|l + (m/2)l² where |g| ≥ ml (always for m ≤ 0),
	// and at least −|g|l otherwise. Along a run of samples near the least level the curve
	// runs along A's level set, the gradient lies across the box, and the box's thinness
	// counts: this rules out about twice as many of the runs a grid solve looks at after its
	// first as the same bound over the run's disc (the benchmark notes give the counts).
	// The cube roots within 2e-8 and k 1e-6 high (CubeRootsOverDisc): the answer is lowered by
	// 1e-6 of the sum of its terms' sizes (the gradient's by its components').
	const Vec2 centre = box.centre;
	const double l = box.halfLength, w = box.halfWidth;
	const double radius = std::sqrt(l * l + w * w);
	DiscCubeRoots roots;
	if (!CubeRootsOverDisc(centre, radius, roots))
		return -std::numeric_limits<double>::infinity();
	const double ax = std::fabs(centre.x), cy = centre.y, inverse = roots.inverse;
	const double c2 = roots.root * roots.root; // |cx|^{2/3}
	const double r2 = centre.x * centre.x + cy * cy;
	const double bend = (2.0 / 3.0) * inverse * cy; // (2/3)|cx|^{−1/3} cy
	const double gx = 2.0 * centre.x - (centre.x > 0.0 ? bend : -bend); // ∂x
	const double gy = 2.0 * cy - c2;
	const EigenvalueTerms terms = EigenvalueTermsOverDisc(centre, radius, roots.k);
	const double m = (2.0 + terms.down) - terms.e;
	const double gu = std::fabs(gx * box.axis.x + gy * box.axis.y), gv = std::fabs(gy * box.axis.x - gx * box.axis.y);
	if (!(std::fabs(m) <= 1e300 && gu <= 1e300 && gv <= 1e300))
		return -std::numeric_limits<double>::infinity();
	const double ml = m * l, mw = m * w;
	const double drop = ((gu >= ml ? 0.5 * ml * l : 0.0) - gu * l) + ((gv >= mw ? 0.5 * mw * w : 0.0) - gv * w);
	const double gradientSize = (2.0 * ax + std::fabs(bend)) + (2.0 * std::fabs(cy) + c2);
	const double curve = 0.5 * (terms.e - terms.down); // (|down| + e)/2: the Hessian beyond 2, halved as in (m/2)|d|²
	const double size = (r2 + c2 * std::fabs(cy)) + (gradientSize * radius + (radius * radius) * (1.0 + curve));
	return ((r2 - c2 * cy) + drop) - 1e-6 * size;
}

bool HeartShape::CurvatureBounds(Vec2 centre, double radius, double& lowest, double& highest) const
{
	// CubeRootsOverDisc's bounds; their sums lowered and raised by 1e-12 of their terms' sizes
	// for rounding (k, 1e-6 high, already covers the cube root's error).
	lowest = -std::numeric_limits<double>::infinity();
	highest = std::numeric_limits<double>::infinity();
	DiscCubeRoots roots;
	if (!CubeRootsOverDisc(centre, radius, roots))
		return false;
	const EigenvalueTerms t = EigenvalueTermsOverDisc(centre, radius, roots.k);
	const double size = 2.0 + (t.up - t.down) + t.e;
	if (!(size <= 1e300))
		return false;
	lowest = ((2.0 + t.down) - t.e) - 1e-12 * size;
	highest = ((2.0 + t.up) + t.e) + 1e-12 * size;
	return true;
}

double HeartShape::LevelUpperBound(Vec2 centre, double radius) const
{
	// Over |x − c| ≤ ρ: x² + y² ≤ (|c| + ρ)². The cusp term −|x|^{2/3} y is at most
	// (|cx| + ρ)^{2/3} (ρ − cy) where the disc reaches y < 0, and where it lies above the x axis
	// at most −dx^{2/3} (cy − ρ) with dx = (|cx| − ρ)₊ (both factors at their smallest).
	// (The cube root by its bounds, as in LevelLowerBound, sides swapped.)
	const double r = Length(centre) + radius;
	const double bottom = centre.y - radius;
	double lower, upper;
	if (bottom < 0.0)
	{
		const double wide = std::fabs(centre.x) + radius;
		CubeRootBounds(wide * wide, lower, upper);
		return r * r - upper * bottom;
	}
	const double dx = std::max(std::fabs(centre.x) - radius, 0.0);
	CubeRootBounds(dx * dx, lower, upper);
	return r * r - lower * bottom;
}

double HeartShape::RadiusAt(Vec2 u, double level) const
{
	// Along x = t·u: α(x) = t² − k t^{5/3} with k = cbrt(ux² uy³). With s = t^{1/3}:
	//   h(s) = s⁶ − k s⁵ − L = 0,  h'(s) = 6s⁵ − 5k s⁴.
	// h(0) = −L < 0 and h has one positive root; h is convex right of it (h'' = s³(30s − 20k) > 0
	// for s > 2k/3, and the root exceeds 5k/6). Starting at s = max(k, 0) + L^{1/6}, where h ≥ 0,
	// Newton descends monotonically onto the root.
	if (!(level > 0.0))
		return 0.0;
	const double k = CubeRoot(u.x * u.x * u.y * u.y * u.y);
	double s = std::max(k, 0.0) + (level == m_alpha ? m_alphaSixth : std::pow(level, 1.0 / 6.0));
	for (int it = 0; it < 100; ++it)
	{
		const double s4 = (s * s) * (s * s);
		const double h = s4 * s * (s - k) - level;
		const double dh = s4 * (6.0 * s - 5.0 * k);
		const double step = h / dh;
		if (!(step > 0.0))
			break; // monotone descent has reached rounding level
		s -= step;
		if (step <= 1e-16 * s)
			break;
	}
	return s * s * s;
}

bool HeartShape::TangencyNewton(Vec2 d, Vec2 start, Vec2 before, Vec2 after, Vec2& x) const
{
	// Unknowns x = (x, y) on one side of the axis: F1 = α(x) − α, F2 = ∇α × d, with the Jacobian
	// rows ∇α and (H d⊥)ᵀ (d⊥ = (d_y, −d_x)). Quadratic from a sample beside the solution.
	const double side = start.x > 0.0 ? 1.0 : -1.0, scale = std::sqrt(m_alpha);
	x = start;
	bool settled = false;
	LevelDerivatives D;
	for (int it = 0; it < 12 && !settled; ++it)
	{
		D = Derivatives(x);
		const Vec2 g = D.gradient;
		const Sym22& H = D.hessian;
		const double f1 = D.value - m_alpha, f2 = g.x * d.y - g.y * d.x;
		const double j21 = H.xx * d.y - H.xy * d.x, j22 = H.xy * d.y - H.yy * d.x;
		const double det = g.x * j22 - g.y * j21;
		if (!(std::fabs(det) > 0.0))
			return false;
		const Vec2 step((f1 * j22 - g.y * f2) / det, (g.x * f2 - j21 * f1) / det);
		x = x - step;
		if (!(x.x * side > 1e-6 * scale) || !IsFinite(x))
			return false; // onto the axis, where the level has its kink: not this method's case
		settled = LengthSquared(step) <= 1e-28 * m_alpha;
	}
	if (!settled)
		return false;
	// A maximum of d·x along the outline: the gradient along d, and the outline convex there
	// (the level's Hessian positive along the tangent); and within the sample's bracket. (The
	// derivatives at the last iterate, a rounding-sized step from x, decide these signs.)
	const Vec2 g = D.gradient, t(-g.y, g.x);
	const Sym22& H = D.hessian;
	const double curvature = t.x * (H.xx * t.x + H.xy * t.y) + t.y * (H.xy * t.x + H.yy * t.y);
	return Dot(g, d) > 0.0 && curvature > 0.0 && Cross(before, x) >= 0.0 && Cross(x, after) >= 0.0;
}

Vec2 HeartShape::Support(Vec2 d) const
{
	// The tip is the support where every x − tip, within m_tip's angle of the vertical, has
	// d·(x − tip) ≤ 0; a margin of 1e-6 of |d| keeps the angle's last digits from deciding.
	const double tipY = -std::sqrt(m_alpha);
	if (std::fabs(d.x) * m_tipSin + d.y * m_tipCos <= -1e-6 * Length(d))
		return Vec2(0.0, tipY);
	const SurfaceSamples& samples = SamplesRef();
	const int best = BestSample(d);
	const Vec2 start = samples.point[size_t(best)];
	const double bestValue = Dot(d, start);
	if (std::fabs(start.x) > 1e-3 * std::sqrt(m_alpha))
	{
		const int n = samples.Count();
		const Vec2 before = samples.point[size_t((best + n - 1) % n)], after = samples.point[size_t((best + 1) % n)];
		Vec2 x;
		if (TangencyNewton(d, start, before, after, x) && Dot(d, x) >= bestValue)
			return x;
	}
	return Shape::Support(d);
}

void HeartShape::SupportBounds(Vec2 d, double& lower, double& upper) const
{
	const SurfaceSamples& samples = SamplesRef();
	const double value = Dot(d, samples.point[size_t(BestSample(d))]);
	const double size = Length(d) * BoundingRadius();
	lower = value - 1e-12 * size;
	upper = value + 4.0 * samples.maxDeviation * Length(d) + 1e-12 * size;
}

std::shared_ptr<HeartShape> MakeHeart(double alpha)
{
	return std::make_shared<HeartShape>(alpha);
}

} // namespace b2a
