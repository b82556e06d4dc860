// b2analytic references: independent long-double references for superellipsoids (3D).
//
// Nothing here calls a 3D solver of the library, nor its shapes' level, radius, support or
// sample functions: every shape is described again from its formula |x/a|^n1 + |y/b|^n2 +
// |z/c|^n3 and evaluated in long double (eps ≈ 1.1e-19), so the references are exact far below
// the tolerances the tests assert on double-precision results. Taken from the library: the
// shapes' parameters and the poses' stored quaternions (the geometry the solver was given).
//
// What is here:
//  - Shape, Pose: the level and its gradient in long double, rotations from the quaternion.
//  - OnLevel: the point of a level set on a ray, by bisection.
//  - SurfaceMin: the smallest level of A over B's level-L surface: a dense latitude–longitude
//    scan of B's surface (uniform angles, unlike the library's spread grid), then Nelder–Mead in
//    long double from the lowest local minima (level exact to ~1e-18; the point to ~1e-9 of the
//    size on smooth minima).
//  - CommonLevel: the fixed point C = G(C) of G(L) = the least level of A over B's solid level-L
//    set (decreasing in L), by bisection on log C.
//  - PerramWertheim: for two ellipsoids, C = max over λ of F(λ) = λ(1 − λ) rᵀ(λA⁻¹ + (1 − λ)B⁻¹)⁻¹r
//    (F is concave) by bisection on the sign of F', 3×3 solves by Cramer's rule.
//  - Polish: Newton in long double on ∇fA + μ∇fB = 0, fA = fB (raw levels, Gaussian
//    elimination), from a given start: the common level's unique solution (convex shapes) to
//    long-double precision.
#pragma once

#include "b2analytic/3d/SuperellipsoidShape.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace b2a::test::ref3
{

using LD = long double;
static_assert(std::numeric_limits<LD>::digits >= 64, "the 3D references need an extended long double");

/// A long-double 3D vector.
struct V3
{
	LD x = 0.0L, y = 0.0L, z = 0.0L;
	LD operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
	LD& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(LD s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline LD Dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 Cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline LD Len(V3 a) { return std::sqrt(Dot(a, a)); }
inline V3 Unit(V3 a) { return (1.0L / Len(a)) * a; }
inline V3 From(Vec3 a) { return {a.x, a.y, a.z}; }
inline Vec3 ToVec(V3 a) { return Vec3(double(a.x), double(a.y), double(a.z)); }
/// Distance between a double point and a long-double point.
inline LD Dist(Vec3 a, V3 b) { return Len(From(a) - b); }

/// |x|^e: repeated multiplication for small integers, else exp(e log x).
inline LD PowL(LD x, LD e)
{
	x = std::fabs(x);
	if (!(x > 0.0L))
		return 0.0L;
	if (e == std::floor(e) && e <= 64.0L)
	{
		LD r = 1.0L, t = x;
		for (int k = int(e); k > 0; k >>= 1)
		{
			if (k & 1) r *= t;
			t *= t;
		}
		return r;
	}
	return std::exp(e * std::log(x));
}

/// A superellipsoid described again from its formula.
struct Shape
{
	LD a[3] = {1, 1, 1}; ///< semi-axes
	LD n[3] = {2, 2, 2}; ///< exponents
	Shape() = default;
	/// The library shape's parameters.
	explicit Shape(const SuperellipsoidShape& s)
	{
		for (int i = 0; i < 3; ++i)
		{
			a[i] = s.Axis(i);
			n[i] = s.Exponent(i);
		}
	}
	/// f at a body point.
	LD Level(V3 x) const { return PowL(x.x / a[0], n[0]) + PowL(x.y / a[1], n[1]) + PowL(x.z / a[2], n[2]); }
	/// ∇f at a body point.
	V3 Gradient(V3 x) const
	{
		V3 g;
		for (int i = 0; i < 3; ++i)
		{
			const LD s = x[i] > 0 ? 1.0L : (x[i] < 0 ? -1.0L : 0.0L);
			g[i] = n[i] / a[i] * s * PowL(x[i] / a[i], n[i] - 1.0L);
		}
		return g;
	}
	/// The diagonal of ∇²f (no mixed terms).
	V3 HessianDiagonal(V3 x) const
	{
		V3 h;
		for (int i = 0; i < 3; ++i)
			h[i] = n[i] * (n[i] - 1.0L) / (a[i] * a[i]) * PowL(x[i] / a[i], n[i] - 2.0L);
		return h;
	}
	/// Largest semi-axis (a length scale).
	LD Size() const { return std::max({a[0], a[1], a[2]}); }
};

/// A pose in long double: centre and rotation matrix from the stored quaternion.
struct Pose
{
	V3 p;
	LD R[3][3];
	explicit Pose(const Pose3& q)
	{
		p = From(q.p);
		const LD n = std::sqrt((LD)q.q.w * q.q.w + (LD)q.q.x * q.q.x + (LD)q.q.y * q.q.y + (LD)q.q.z * q.q.z);
		const LD w = q.q.w / n, x = q.q.x / n, y = q.q.y / n, z = q.q.z / n;
		R[0][0] = 1 - 2 * (y * y + z * z); R[0][1] = 2 * (x * y - w * z); R[0][2] = 2 * (x * z + w * y);
		R[1][0] = 2 * (x * y + w * z); R[1][1] = 1 - 2 * (x * x + z * z); R[1][2] = 2 * (y * z - w * x);
		R[2][0] = 2 * (x * z - w * y); R[2][1] = 2 * (y * z + w * x); R[2][2] = 1 - 2 * (x * x + y * y);
	}
	V3 Rotate(V3 v) const
	{
		return {R[0][0] * v.x + R[0][1] * v.y + R[0][2] * v.z, R[1][0] * v.x + R[1][1] * v.y + R[1][2] * v.z,
		        R[2][0] * v.x + R[2][1] * v.y + R[2][2] * v.z};
	}
	V3 InvRotate(V3 v) const
	{
		return {R[0][0] * v.x + R[1][0] * v.y + R[2][0] * v.z, R[0][1] * v.x + R[1][1] * v.y + R[2][1] * v.z,
		        R[0][2] * v.x + R[1][2] * v.y + R[2][2] * v.z};
	}
	V3 ToBody(V3 X) const { return InvRotate(X - p); }
	V3 ToWorld(V3 x) const { return Rotate(x) + p; }

	/// The pose at time t of a body starting at `start`, moving with velocity v and turning with
	/// the world angular velocity w: centre p + v·t, rotation exp(t·[w]×)·R₀ (Rodrigues' formula).
	static Pose Moving(const Pose3& start, Vec3 v, Vec3 w, LD t)
	{
		Pose m(start);
		m.p = m.p + t * From(v);
		const V3 wl = From(w);
		const LD speed = Len(wl);
		if (!(speed > 0.0L))
			return m;
		const V3 u = (1.0L / speed) * wl;
		const LD th = speed * t, s = std::sin(th), c1 = 1.0L - std::cos(th);
		const LD K[3][3] = {{0, -u.z, u.y}, {u.z, 0, -u.x}, {-u.y, u.x, 0}};
		LD E[3][3];
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
			{
				LD k2 = 0.0L;
				for (int k = 0; k < 3; ++k)
					k2 += K[i][k] * K[k][j];
				E[i][j] = (i == j ? 1.0L : 0.0L) + s * K[i][j] + c1 * k2;
			}
		LD R[3][3];
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				R[i][j] = E[i][0] * m.R[0][j] + E[i][1] * m.R[1][j] + E[i][2] * m.R[2][j];
		std::copy(&R[0][0], &R[0][0] + 9, &m.R[0][0]);
		return m;
	}
};

/// The point of the level-L set on the ray from the centre along the body direction d, by
/// bisection on the scale (f grows along the ray).
inline V3 OnLevel(const Shape& s, V3 d, LD L)
{
	LD lo = 0.0L, hi = 1.0L;
	while (s.Level(hi * d) < L)
		hi *= 2.0L;
	for (int k = 0; k < 200 && hi - lo > 1e-21L * hi; ++k)
	{
		const LD mid = 0.5L * (lo + hi);
		(s.Level(mid * d) < L ? lo : hi) = mid;
	}
	return (0.5L * (lo + hi)) * d;
}

/// Nelder–Mead in two variables, long double, to a simplex of `tol` across.
inline std::pair<LD, LD> MinimizeNM(const std::function<LD(LD, LD)>& f, LD step, LD tol, LD* value = nullptr)
{
	LD p[3][2] = {{0, 0}, {step, 0}, {0, step}}, v[3];
	for (int i = 0; i < 3; ++i)
		v[i] = f(p[i][0], p[i][1]);
	for (int it = 0; it < 4000; ++it)
	{
		int o[3] = {0, 1, 2};
		std::sort(o, o + 3, [&](int i, int j) { return v[i] < v[j]; });
		LD q[3][2], w[3];
		for (int i = 0; i < 3; ++i)
		{
			q[i][0] = p[o[i]][0];
			q[i][1] = p[o[i]][1];
			w[i] = v[o[i]];
		}
		std::copy(&q[0][0], &q[0][0] + 6, &p[0][0]);
		std::copy(w, w + 3, v);
		LD size = 0;
		for (int i = 1; i < 3; ++i)
			size = std::max({size, std::fabs(p[i][0] - p[0][0]), std::fabs(p[i][1] - p[0][1])});
		if (size < tol)
			break;
		const LD c0 = 0.5L * (p[0][0] + p[1][0]), c1 = 0.5L * (p[0][1] + p[1][1]);
		auto at = [&](LD t, LD r[2]) {
			r[0] = c0 + t * (p[2][0] - c0);
			r[1] = c1 + t * (p[2][1] - c1);
			return f(r[0], r[1]);
		};
		LD r[2], e[2], k[2];
		const LD vr = at(-1, r);
		if (vr < v[0])
		{
			const LD ve = at(-2, e);
			if (ve < vr) { p[2][0] = e[0]; p[2][1] = e[1]; v[2] = ve; }
			else { p[2][0] = r[0]; p[2][1] = r[1]; v[2] = vr; }
			continue;
		}
		if (vr < v[1]) { p[2][0] = r[0]; p[2][1] = r[1]; v[2] = vr; continue; }
		const bool outside = vr < v[2];
		const LD vk = at(outside ? -0.5L : 0.5L, k);
		if (vk < (outside ? vr : v[2])) { p[2][0] = k[0]; p[2][1] = k[1]; v[2] = vk; continue; }
		for (int i = 1; i < 3; ++i)
		{
			p[i][0] = 0.5L * (p[0][0] + p[i][0]);
			p[i][1] = 0.5L * (p[0][1] + p[i][1]);
			v[i] = f(p[i][0], p[i][1]);
		}
	}
	if (value)
		*value = v[0];
	return {p[0][0], p[0][1]};
}

/// The smallest level of A over B's level-L surface (see the file's header).
struct SurfaceMinimum
{
	LD level = 0.0L; ///< A's level there
	V3 point;        ///< the world point on B's level-L surface
};
inline SurfaceMinimum SurfaceMin(const Shape& A, const Pose& pa, const Shape& B, const Pose& pb, LD L, int rings = 48)
{
	const int perRing = 2 * rings;
	const LD pi = 3.141592653589793238462643383279502884L;
	auto direction = [&](LD eta, LD omega) {
		return V3{B.a[0] * std::cos(eta) * std::cos(omega), B.a[1] * std::cos(eta) * std::sin(omega), B.a[2] * std::sin(eta)};
	};
	auto levelAt = [&](V3 d) { return A.Level(pa.ToBody(pb.ToWorld(OnLevel(B, d, L)))); };
	std::vector<LD> value(size_t(rings) * perRing);
	std::vector<V3> dir(value.size());
	for (int r = 0; r < rings; ++r)
		for (int k = 0; k < perRing; ++k)
		{
			const LD eta = -pi / 2 + pi * (r + 0.5L) / rings, omega = 2 * pi * k / perRing;
			dir[size_t(r) * perRing + k] = direction(eta, omega);
			value[size_t(r) * perRing + k] = levelAt(dir[size_t(r) * perRing + k]);
		}
	std::vector<size_t> minima;
	for (int r = 0; r < rings; ++r)
		for (int k = 0; k < perRing; ++k)
		{
			const size_t i = size_t(r) * perRing + k;
			bool lowest = true;
			for (int dr = -1; dr <= 1; ++dr)
				for (int dk = -1; dk <= 1; ++dk)
				{
					const int rr = r + dr;
					if (rr < 0 || rr >= rings)
						continue;
					lowest = lowest && value[i] <= value[size_t(rr) * perRing + (k + dk + perRing) % perRing];
				}
			if (lowest)
				minima.push_back(i);
		}
	std::sort(minima.begin(), minima.end(), [&](size_t i, size_t j) { return value[i] < value[j]; });
	SurfaceMinimum best;
	best.level = std::numeric_limits<LD>::infinity();
	for (size_t c = 0; c < std::min<size_t>(3, minima.size()); ++c)
	{
		const V3 d0 = dir[minima[c]];
		const V3 helper = std::fabs(d0.x) < 0.5L * Len(d0) ? V3{1, 0, 0} : V3{0, 1, 0};
		const V3 e1 = Len(d0) * Unit(Cross(d0, helper)), e2 = Len(d0) * Unit(Cross(d0, e1));
		auto f = [&](LD u, LD v) { return levelAt(d0 + u * e1 + v * e2); };
		LD value0;
		const auto m = MinimizeNM(f, 0.5L * pi / rings, 1e-16L, &value0);
		if (value0 < best.level)
		{
			best.level = value0;
			best.point = pb.ToWorld(OnLevel(B, d0 + m.first * e1 + m.second * e2, L));
		}
	}
	return best;
}

/// The common level of two convex shapes: C = G(C), G(L) = the least level of A over B's solid
/// level-L set (0 where it holds A's centre), by bisection on log L.
inline SurfaceMinimum CommonLevel(const Shape& A, const Pose& pa, const Shape& B, const Pose& pb, int rings = 48)
{
	const LD centre = B.Level(pb.ToBody(pa.p));
	auto G = [&](LD L) {
		if (L >= centre)
			return SurfaceMinimum{0.0L, pa.p};
		return SurfaceMin(A, pa, B, pb, L, rings);
	};
	// h(u) = log G(e^u) − u decreases; the Illinois variant of regula falsi on it.
	LD lo = std::log(1e-6L), hi = std::log(centre);
	auto h = [&](LD u) { return std::log(G(std::exp(u)).level) - u; };
	while (h(lo) < 0.0L)
		lo -= std::log(1e3L);
	LD hLo = h(lo), hHi = -std::numeric_limits<LD>::infinity();
	// G(centre) = 0: step down until h is finite and negative.
	for (hi = std::log(centre) - 1e-6L; !(std::isfinite(hHi = h(hi)) && hHi < 0.0L); hi = 0.5L * (hi + lo))
		;
	int side = 0;
	for (int k = 0; k < 100 && hi - lo > 1e-18L; ++k)
	{
		const LD u = (lo * hHi - hi * hLo) / (hHi - hLo);
		const LD hu = h(u);
		if (hu >= 0.0L)
		{
			lo = u;
			hLo = hu;
			if (side == -1) hHi *= 0.5L;
			side = -1;
		}
		else
		{
			hi = u;
			hHi = hu;
			if (side == 1) hLo *= 0.5L;
			side = 1;
		}
		if (hu == 0.0L)
			break;
	}
	const LD C = std::exp(0.5L * (lo + hi));
	SurfaceMinimum m = G(C);
	m.level = C;
	return m;
}

/// A 3×3 solve by Cramer's rule.
inline V3 Solve3(const LD M[3][3], V3 r)
{
	auto det = [](const LD m[3][3]) {
		return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
		       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
	};
	const LD d = det(M);
	V3 x;
	for (int c = 0; c < 3; ++c)
	{
		LD m[3][3];
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				m[i][j] = j == c ? r[i] : M[i][j];
		x[c] = det(m) / d;
	}
	return x;
}

/// Perram–Wertheim for two ellipsoids (exponents 2): the common level and its point.
inline SurfaceMinimum PerramWertheim(const Shape& A, const Pose& pa, const Shape& B, const Pose& pb)
{
	LD Ai[3][3], Bi[3][3];
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
		{
			Ai[i][j] = Bi[i][j] = 0.0L;
			for (int k = 0; k < 3; ++k)
			{
				Ai[i][j] += pa.R[i][k] * A.a[k] * A.a[k] * pa.R[j][k];
				Bi[i][j] += pb.R[i][k] * B.a[k] * B.a[k] * pb.R[j][k];
			}
		}
	const V3 r = pb.p - pa.p;
	auto z = [&](LD l) {
		LD G[3][3];
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				G[i][j] = l * Ai[i][j] + (1.0L - l) * Bi[i][j];
		return Solve3(G, r);
	};
	auto F = [&](LD l) { return l * (1.0L - l) * Dot(r, z(l)); };
	// F is concave; its maximiser is the root of F'(λ) = (1 − 2λ) rᵀz − λ(1 − λ) zᵀ(A⁻¹ − B⁻¹)z,
	// by bisection (a golden-section search would give λ only to √eps).
	auto slope = [&](LD l) {
		const V3 zl = z(l);
		V3 w;
		for (int i = 0; i < 3; ++i)
			w[i] = (Ai[i][0] - Bi[i][0]) * zl.x + (Ai[i][1] - Bi[i][1]) * zl.y + (Ai[i][2] - Bi[i][2]) * zl.z;
		return (1.0L - 2.0L * l) * Dot(r, zl) - l * (1.0L - l) * Dot(zl, w);
	};
	LD lo = 0.0L, hi = 1.0L;
	for (int k = 0; k < 200 && hi - lo > 1e-21L; ++k)
	{
		const LD mid = 0.5L * (lo + hi);
		(slope(mid) > 0.0L ? lo : hi) = mid;
	}
	const LD l = 0.5L * (lo + hi);
	const V3 zl = z(l);
	SurfaceMinimum m;
	m.level = F(l);
	V3 Az;
	for (int i = 0; i < 3; ++i)
		Az[i] = Ai[i][0] * zl.x + Ai[i][1] * zl.y + Ai[i][2] * zl.z;
	m.point = pa.p + l * Az;
	return m;
}

/// Newton in long double on ∇fA + μ∇fB = 0, fA − fB = 0 from (X, μ): the common level's
/// solution, with the residual's norm relative to its terms in `residual` where given.
inline SurfaceMinimum Polish(const Shape& A, const Pose& pa, const Shape& B, const Pose& pb, V3 X, LD mu, LD* residual = nullptr)
{
	LD res = 0.0L;
	for (int it = 0; it < 60; ++it)
	{
		const V3 xa = pa.ToBody(X), xb = pb.ToBody(X);
		const V3 ga = pa.Rotate(A.Gradient(xa)), gb = pb.Rotate(B.Gradient(xb));
		const V3 ha = A.HessianDiagonal(xa), hb = B.HessianDiagonal(xb);
		LD J[4][5];
		for (int i = 0; i < 3; ++i)
		{
			for (int j = 0; j < 3; ++j)
			{
				LD s = 0.0L;
				for (int k = 0; k < 3; ++k)
					s += pa.R[i][k] * ha[k] * pa.R[j][k] + mu * pb.R[i][k] * hb[k] * pb.R[j][k];
				J[i][j] = s;
			}
			J[i][3] = gb[i];
			J[i][4] = -(ga[i] + mu * gb[i]);
			J[3][i] = ga[i] - gb[i];
		}
		J[3][3] = 0.0L;
		J[3][4] = -(A.Level(xa) - B.Level(xb));
		res = std::sqrt((J[0][4] * J[0][4] + J[1][4] * J[1][4] + J[2][4] * J[2][4]) / Dot(ga, ga) +
		                J[3][4] * J[3][4] / (A.Level(xa) * A.Level(xa)));
		// Gaussian elimination with partial pivoting.
		for (int c = 0; c < 4; ++c)
		{
			int piv = c;
			for (int i = c + 1; i < 4; ++i)
				if (std::fabs(J[i][c]) > std::fabs(J[piv][c]))
					piv = i;
			for (int j = 0; j < 5; ++j)
				std::swap(J[c][j], J[piv][j]);
			for (int i = c + 1; i < 4; ++i)
			{
				const LD m = J[i][c] / J[c][c];
				for (int j = c; j < 5; ++j)
					J[i][j] -= m * J[c][j];
			}
		}
		LD d[4];
		for (int i = 3; i >= 0; --i)
		{
			LD s = J[i][4];
			for (int j = i + 1; j < 4; ++j)
				s -= J[i][j] * d[j];
			d[i] = s / J[i][i];
		}
		X = X + V3{d[0], d[1], d[2]};
		mu += d[3];
		if (std::fabs(d[0]) + std::fabs(d[1]) + std::fabs(d[2]) < 1e-19L * (1.0L + Len(X)))
			break;
	}
	if (residual)
		*residual = res;
	return {A.Level(pa.ToBody(X)), X};
}

} // namespace b2a::test::ref3
