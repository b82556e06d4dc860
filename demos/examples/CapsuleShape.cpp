// Example: the capsule shape kind, its closed forms and its registration.
#include "CapsuleShape.h"

#include <algorithm>
#include <cmath>

using namespace b2a;

namespace example
{

std::atomic<long> g_closedFormContacts{0};

CapsuleShape::CapsuleShape(double h, double r)
	: Shape(CapsuleKind(), 1.0, /*convex*/ true, /*smoothConvex*/ false, /*levelPower*/ 1.0), m_h(h), m_r(r)
{
	if (!std::isfinite(h) || !(h >= 0.0))
		throw InvalidParameter("capsule", "h", "must be finite and >= 0", h);
	if (!std::isfinite(r) || !(r > 0.0))
		throw InvalidParameter("capsule", "r", "must be finite and > 0", r);
	SetDerivativesCheap();
	const MassProperties mass = ClosedFormMass(h, r);
	Finalize(h + r, &mass);
}

std::string CapsuleShape::Describe() const
{
	return "capsule(h=" + FormatNumber(m_h) + ", r=" + FormatNumber(m_r) + ")";
}

double CapsuleShape::Level(Vec2 x) const
{
	const double dx = std::max(std::fabs(x.x) - m_h, 0.0);
	return (dx * dx + x.y * x.y) / (m_r * m_r);
}

LevelDerivatives CapsuleShape::Derivatives(Vec2 x) const
{
	// Beside the segment, λ = y²/r²; beyond its ends, |x − end|²/r².
	const double k = 2.0 / (m_r * m_r);
	LevelDerivatives d;
	const double dx = std::fabs(x.x) - m_h;
	if (dx <= 0.0)
	{
		d.value = x.y * x.y / (m_r * m_r);
		d.gradient = Vec2(0.0, k * x.y);
		d.hessian = Sym22{0.0, 0.0, k};
		return d;
	}
	const Vec2 p(std::copysign(dx, x.x), x.y);
	d.value = LengthSquared(p) / (m_r * m_r);
	d.gradient = k * p;
	d.hessian = Sym22{k, 0.0, k};
	return d;
}

double CapsuleShape::RadiusAt(Vec2 u, double level) const
{
	if (!(level > 0.0))
		return 0.0;
	const double rho = m_r * std::sqrt(level);
	const double along = std::fabs(u.x), across = std::fabs(u.y);
	// On a flat side where it meets it there, else on a cap: |t·u − end| = ρ, the larger root.
	if (across > 0.0 && rho * along <= m_h * across)
		return rho / across;
	return m_h * along + std::sqrt(std::max(rho * rho - m_h * m_h * across * across, 0.0));
}

Vec2 CapsuleShape::Support(Vec2 d) const
{
	const double length = Length(d);
	const Vec2 end(d.x >= 0.0 ? m_h : -m_h, 0.0);
	return length > 0.0 ? end + (m_r / length) * d : end + Vec2(m_r, 0.0);
}

double CapsuleShape::SupportValue(Vec2 d) const
{
	return m_h * std::fabs(d.x) + m_r * Length(d);
}

Box CapsuleShape::ComputeAABB(const Pose& pose) const
{
	const Vec2 axis = Rotate(pose.q, Vec2(1.0, 0.0));
	const Vec2 half(m_h * std::fabs(axis.x) + m_r, m_h * std::fabs(axis.y) + m_r);
	Box box;
	box.lower = pose.p - half;
	box.upper = pose.p + half;
	return box;
}

void CapsuleShape::Segment(const Pose& pose, Vec2& p, Vec2& q) const
{
	p = ToWorld(pose, Vec2(-m_h, 0.0));
	q = ToWorld(pose, Vec2(m_h, 0.0));
}

MassProperties CapsuleShape::ClosedFormMass(double h, double r)
{
	// The rectangle 2h × 2r and a disc of radius r split at x = ±h: the caps' ∫x² is
	// πr²h² + (8/3)hr³ + πr⁴/4 (the half discs' centroids at 4r/3π beyond the ends).
	const double pi = kPi;
	MassProperties m;
	m.area = 4.0 * h * r + pi * r * r;
	m.Ixx = (4.0 / 3.0) * h * r * r * r + 0.25 * pi * r * r * r * r;
	m.Iyy = (4.0 / 3.0) * r * h * h * h + pi * r * r * h * h + (8.0 / 3.0) * h * r * r * r + 0.25 * pi * r * r * r * r;
	m.Ixy = 0.0;
	m.polarMoment = m.Ixx + m.Iyy;
	return m;
}

std::shared_ptr<CapsuleShape> MakeCapsule(double h, double r)
{
	return std::make_shared<CapsuleShape>(h, r);
}

namespace
{
// A capsule's or a circle's core (its segment; a circle's is its centre) and radius, posed.
struct Core
{
	Vec2 p, q;
	double r;
};
Core CoreOf(const Shape& s, const Pose& pose)
{
	Core c;
	if (const auto* capsule = dynamic_cast<const CapsuleShape*>(&s))
	{
		capsule->Segment(pose, c.p, c.q);
		c.r = capsule->Radius();
	}
	else
	{
		c.p = c.q = pose.p; // a circle (the table calls these functions for no other kind)
		c.r = s.BoundingRadius();
	}
	return c;
}

// The point of segment p–q nearest x.
Vec2 Nearest(Vec2 p, Vec2 q, Vec2 x)
{
	const Vec2 e = q - p;
	const double ee = LengthSquared(e);
	const double t = ee > 0.0 ? std::clamp(Dot(x - p, e) / ee, 0.0, 1.0) : 0.0;
	return p + t * e;
}

// The closest points of two segments that do not cross: one of them is an end of its segment,
// so the nearest of the four ends' nearest points. False where the segments cross or touch
// (distance at rounding level of the pair's size): no normal between them.
bool ClosestPoints(const Core& a, const Core& b, Vec2& qa, Vec2& qb)
{
	// Segments crossing properly (each one's ends strictly on both sides of the other's line).
	auto side = [](Vec2 o, Vec2 e, Vec2 x) { return Cross(e - o, x - o); };
	auto opposite = [](double s, double t) { return (s > 0.0 && t < 0.0) || (s < 0.0 && t > 0.0); };
	if (opposite(side(b.p, b.q, a.p), side(b.p, b.q, a.q)) && opposite(side(a.p, a.q, b.p), side(a.p, a.q, b.q)))
		return false;
	double best = -1.0;
	auto consider = [&](Vec2 x, Vec2 y) {
		const double d = LengthSquared(y - x);
		if (best < 0.0 || d < best)
		{
			best = d;
			qa = x;
			qb = y;
		}
	};
	consider(a.p, Nearest(b.p, b.q, a.p));
	consider(a.q, Nearest(b.p, b.q, a.q));
	consider(Nearest(a.p, a.q, b.p), b.p);
	consider(Nearest(a.p, a.q, b.q), b.q);
	const double tiny = 1e-12 * (a.r + b.r + Distance(a.p, a.q) + Distance(b.p, b.q));
	return std::sqrt(best) > tiny;
}

// The common level of the two cores' capsules from their closest points (see CapsuleLevel).
LevelResult LevelOfCores(const Core& a, const Core& b, Vec2 qa, Vec2 qb)
{
	const double d = Distance(qa, qb);
	LevelResult r;
	r.status = SolveStatus::converged;
	r.method = SolveMethod::closedForm;
	r.normal = (qb - qa) / d;
	r.point = qa + (a.r / (a.r + b.r)) * (qb - qa);
	const double s = d / (a.r + b.r);
	r.level = s * s;
	r.multiplier = b.r / a.r; // |∇λA| = 2s/rA, |∇λB| = 2s/rB at the point, opposed
	return r;
}
} // namespace

ContactResult CapsuleContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                             WarmStart* warm)
{
	const Core ca = CoreOf(a, pa), cb = CoreOf(b, pb);
	Vec2 qa, qb;
	if (!ClosestPoints(ca, cb, qa, qb))
		return GridContact(a, pa, b, pb, options, warm);
	++g_closedFormContacts;
	const LevelResult level = LevelOfCores(ca, cb, qa, qb);
	ContactResult c;
	c.status = level.status;
	c.method = level.method;
	c.level = level.level;
	c.point = level.point;
	c.normal = level.normal;
	c.pointA = qa + ca.r * c.normal;
	c.pointB = qb - cb.r * c.normal;
	c.separation = Distance(qa, qb) - ca.r - cb.r;
	c.touching = c.separation <= 0.0;
	return c;
}

LevelResult CapsuleLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                         const WarmStart*, LevelSlide*)
{
	const Core ca = CoreOf(a, pa), cb = CoreOf(b, pb);
	Vec2 qa, qb;
	if (!ClosestPoints(ca, cb, qa, qb))
		return SolveCommonLevelGrid(a, pa, b, pb, options);
	return LevelOfCores(ca, cb, qa, qb);
}

ShapeKind CapsuleKind()
{
	// Registered once, before the first capsule exists (a function-local static: thread-safe).
	static const ShapeKind kind = [] {
		const ShapeKind capsule = RegisterShapeKind("capsule", 2, SolverClass::convex);
		RegisterContactFunction(capsule, capsule, &CapsuleContact);
		RegisterContactFunction(capsule, BuiltinKinds::circle, &CapsuleContact);
		RegisterLevelFunction(capsule, capsule, &CapsuleLevel);
		RegisterLevelFunction(capsule, BuiltinKinds::circle, &CapsuleLevel);
		return capsule;
	}();
	return kind;
}

} // namespace example
