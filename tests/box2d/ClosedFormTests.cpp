// b2analytic tests: rigid bodies of analytic shape against the closed forms of rigid-body
// mechanics. An ellipse rocking on the floor, bodies sticking, sliding and rolling on an
// incline, the contact forces of a stack, and bounce heights. Game units (metres, kilograms,
// g = 10 m/s², 8 velocity and 3 position iterations), 60 Hz unless a test says why it needs a
// finer step. docs/validation/rigid.md shows the measured values beside the references.
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
const double kG = 10.0;

Vec2 ToVec(b2Vec2 v) { return Vec2(v.x, v.y); }

// Distance from a body's origin to its lowest point along −`normal` (world) at body angle
// `angle`: where to place it so that it touches a surface with that outward normal.
double SupportDepth(const Shape& shape, double angle, Vec2 normal)
{
	const Rot q(angle);
	return -Dot(Rotate(q, shape.Support(InvRotate(q, -normal))), normal);
}

// Least-squares fit of s(t) = s0 + v0 t + a t²/2: returns a.
double FitAcceleration(const std::vector<double>& t, const std::vector<double>& s)
{
	// Normal equations of the basis (1, t, t²) about the mean time, by Cramer's rule.
	double tm = 0.0;
	for (double x : t)
		tm += x;
	tm /= double(t.size());
	double m[3][3] = {}, r[3] = {};
	for (size_t i = 0; i < t.size(); ++i)
	{
		const double x = t[i] - tm, basis[3] = {1.0, x, x * x};
		for (int j = 0; j < 3; ++j)
		{
			r[j] += basis[j] * s[i];
			for (int k = 0; k < 3; ++k)
				m[j][k] += basis[j] * basis[k];
		}
	}
	auto det = [](double a[3][3]) {
		return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
		       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
	};
	double m2[3][3];
	for (int j = 0; j < 3; ++j)
		for (int k = 0; k < 3; ++k)
			m2[j][k] = k == 2 ? r[j] : m[j][k];
	return 2.0 * det(m2) / det(m);
}

// Period of an oscillating signal from its zero crossings (linearly interpolated): twice the
// mean spacing between the first and last crossing. Also the number of crossings.
std::pair<double, int> PeriodFromZeroCrossings(const std::vector<double>& t, const std::vector<double>& x)
{
	std::vector<double> crossings;
	for (size_t i = 1; i < x.size(); ++i)
		if ((x[i - 1] < 0.0) != (x[i] < 0.0))
			crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * x[i - 1] / (x[i - 1] - x[i]));
	if (crossings.size() < 2)
		return {0.0, int(crossings.size())};
	return {2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1), int(crossings.size())};
}
} // namespace

TEST_CASE("an ellipse rocking on the floor has the small-oscillation period of its curvature and inertia")
{
	// An ellipse x²/a² + y²/b² ≤ 1 (a > b) lying on its flat side rolls without slipping about
	// its lowest point, where the radius of curvature is ρ = a²/b; its centre of mass is b above
	// the contact. Tilted by θ its centre rises by (ρ − b)θ²/2, and it turns about the contact
	// point with inertia I_cm + m b², I_cm = m(a² + b²)/4, so ω² = m g (ρ − b) / (I_cm + m b²).
	// Released from rest at 0.05 rad the amplitude correction to the period is of order θ²
	// (0.25 %) and the step's (ω Δt)²/24 under 0.05 %: the 1.5 % tolerance leaves room for the
	// contact point resting a slop (5 mm) inside the floor and the discrete contact point.
	struct Case
	{
		double a, b;
	};
	for (const Case c : {Case{1.0, 0.5}, Case{0.8, 0.5}, Case{0.6, 0.25}})
	{
		CAPTURE(c.a);
		CAPTURE(c.b);
		b2World world(b2Vec2(0.0f, float(-kG)));
		world.SetAllowSleeping(false);
		MakeFloor(world);
		const auto shape = MakeEllipse(c.a, c.b);
		const double theta0 = 0.05;
		const double y0 = SupportDepth(*shape, theta0, Vec2(0.0, 1.0)) + b2_polygonRadius - b2_linearSlop;
		b2Body* body = MakeParticle(world, shape, 0.0f, float(y0), float(theta0), 1.0f, 1.0f);
		const double rho = c.a * c.a / c.b, inertia = (c.a * c.a + c.b * c.b) / 4.0 + c.b * c.b; // per unit mass
		const double expected = 2.0 * kPi / std::sqrt(kG * (rho - c.b) / inertia);
		// Box2D's inertia is the analytic one.
		CHECK(body->GetInertia() == doctest::Approx(body->GetMass() * (c.a * c.a + c.b * c.b) / 4.0).epsilon(1e-5));
		std::vector<double> t, angle;
		const double dt = 1.0 / 60.0;
		const int steps = int(std::ceil(5.2 * expected / dt)); // five periods: ten crossings
		double maxSlip = 0.0;
		for (int i = 1; i <= steps; ++i)
		{
			world.Step(float(dt), 8, 3);
			t.push_back(i * dt);
			angle.push_back(body->GetAngle());
			// Rolling without slipping: the centre moves by −b Δθ horizontally (to first order;
			// the contact rolls ρ Δθ, the centre swings (ρ − b) Δθ back).
			maxSlip = std::max(maxSlip, std::fabs(body->GetPosition().x + c.b * (body->GetAngle() - theta0)));
		}
		const auto [period, crossings] = PeriodFromZeroCrossings(t, angle);
		CHECK(crossings >= 10);
		CHECK(period == doctest::Approx(expected).epsilon(0.015));
		MESSAGE("rocking a=" << c.a << " b=" << c.b << ": period " << period << " s, closed form " << expected << " s");
		CHECK(maxSlip < 0.05 * c.b * theta0); // rolls, does not slide: within 5 % of the swing
	}
}

TEST_CASE("on an incline a disc, an ellipse and a block stick below tan(angle) = mu and slide or roll above at the textbook rates")
{
	// Ramp and body both have friction μ (Box2D mixes them as √(μ₁μ₂) = μ). Below tan θ = μ
	// a block and an ellipse stick; above it they slide at g (sin θ − μ cos θ). A disc rolls
	// without slipping at (2/3) g sin θ when μ ≥ tan θ / 3, and otherwise slides at
	// g (sin θ − μ cos θ) while spinning up at α = 2 μ g cos θ / r. The ellipse is placed at the
	// tilt where the line from its centre to the contact is along the contact force it needs
	// (vertical when sticking, at atan μ from the normal when sliding), so that it does not rock.
	// Accelerations are least-squares fits of the position along the ramp over 0.25–1.25 s.
	struct Case
	{
		const char* name;
		ShapePtr shape;
		double degrees, mu;
		double expected;   // acceleration along the ramp; 0: sticks
		double spin = 0.0; // expected angular acceleration (disc sliding), 0: not checked
	};
	const auto disc = MakeCircle(0.4), ellipse = MakeEllipse(0.6, 0.3), block = MakeSuperellipse(0.5, 0.4, 8.0, 8.0);
	auto rate = [](double deg, double mu) { return kG * (std::sin(deg * kPi / 180.0) - mu * std::cos(deg * kPi / 180.0)); };
	const double th30 = kPi / 6.0;
	const std::vector<Case> cases = {
		{"block", block, 20.0, 0.5, 0.0},
		{"block", block, 25.0, 0.5, 0.0}, // tan 25° = 0.466, just under μ
		{"block", block, 30.0, 0.5, rate(30.0, 0.5)},
		{"block", block, 40.0, 0.5, rate(40.0, 0.5)},
		{"block", block, 30.0, 0.1, rate(30.0, 0.1)},
		{"ellipse", ellipse, 20.0, 0.5, 0.0},
		{"ellipse", ellipse, 25.0, 0.5, 0.0},
		{"ellipse", ellipse, 30.0, 0.5, rate(30.0, 0.5)},
		{"ellipse", ellipse, 40.0, 0.5, rate(40.0, 0.5)},
		{"disc", disc, 30.0, 0.6, 2.0 / 3.0 * kG * std::sin(th30)},
		{"disc", disc, 30.0, 0.2, 2.0 / 3.0 * kG * std::sin(th30)}, // μ just over tan 30° / 3 = 0.19
		{"disc", disc, 30.0, 0.1, rate(30.0, 0.1), 2.0 * 0.1 * kG * std::cos(th30) / 0.4},
	};
	for (const Case& c : cases)
	{
		const std::string name = c.name;
		CAPTURE(name);
		CAPTURE(c.degrees);
		CAPTURE(c.mu);
		const double theta = c.degrees * kPi / 180.0;
		const Vec2 down(std::cos(theta), -std::sin(theta)), normal(std::sin(theta), std::cos(theta));
		b2World world(b2Vec2(0.0f, float(-kG)));
		world.SetAllowSleeping(false);
		b2BodyDef gd;
		b2EdgeShape ramp;
		ramp.SetTwoSided(b2Vec2(float(-20.0 * down.x), float(-20.0 * down.y)), b2Vec2(float(20.0 * down.x), float(20.0 * down.y)));
		world.CreateBody(&gd)->CreateFixture(&ramp, 0.0f)->SetFriction(float(c.mu));
		// The body's tilt: the contact force's direction F ∝ normal − k·down, k = tan θ when
		// sticking (F vertical) or μ when sliding; the centre-to-contact line must lie along −F.
		const double k = c.expected == 0.0 ? std::tan(theta) : c.mu;
		const Vec2 force = normal - k * down;
		auto torque = [&](double angle) {
			const Rot q(angle);
			return Cross(Rotate(q, c.shape->Support(InvRotate(q, -normal))), force);
		};
		double lo = -theta - 0.5, hi = -theta + 0.5, angle = -theta;
		if (torque(lo) * torque(hi) < 0.0 && name == "ellipse")
		{
			for (int i = 0; i < 60; ++i) // bisection to double precision
			{
				const double mid = 0.5 * (lo + hi);
				(torque(lo) * torque(mid) <= 0.0 ? hi : lo) = mid;
			}
			angle = 0.5 * (lo + hi);
		}
		const Vec2 start = -8.0 * down + (SupportDepth(*c.shape, angle, normal) + b2_polygonRadius - b2_linearSlop) * normal;
		b2Body* body = MakeParticle(world, c.shape, float(start.x), float(start.y), float(angle), 1.0f, float(c.mu));
		const double dt = 1.0 / 60.0;
		std::vector<double> t, s;
		double s0 = 0.0, s1 = 0.0, w0 = 0.0, w1 = 0.0;
		for (int i = 1; i <= 75; ++i)
		{
			world.Step(float(dt), 8, 3);
			const double along = Dot(ToVec(body->GetPosition()), down);
			if (i == 15)
				s0 = along, w0 = body->GetAngularVelocity();
			if (i >= 15)
				t.push_back(i * dt), s.push_back(along);
			s1 = along, w1 = body->GetAngularVelocity();
		}
		if (c.expected == 0.0)
		{
			MESSAGE(name << " at " << c.degrees << " deg, mu " << c.mu << ": moved " << s1 - s0 << " m in 1 s (sticks)");
			CHECK(std::fabs(s1 - s0) < 1e-3);
		}
		else
		{
			const double a = FitAcceleration(t, s);
			MESSAGE(name << " at " << c.degrees << " deg, mu " << c.mu << ": a = " << a << " m/s^2, closed form " << c.expected);
			CHECK(a == doctest::Approx(c.expected).epsilon(0.01));
			if (c.spin != 0.0)
				CHECK(-(w1 - w0) / 1.0 == doctest::Approx(c.spin).epsilon(0.01)); // clockwise as it goes down-right
		}
	}
}

TEST_CASE("in a stack of superellipses each contact carries the weight above it")
{
	// Five bodies of different sizes, exponents and densities, each resting flat on the one
	// below, the top one an ellipse (stable on its flat side: ρ = a²/b > b). At rest the normal
	// force through each contact is g times the mass above it, which Box2D's impulses give as
	// impulse / Δt. Averaged over the last 0.5 s of 3 s at 60 Hz. Warm-started impulses of a
	// resting stack converge: they match to float precision, and 0.1 % leaves room for that.
	struct Layer
	{
		ShapePtr shape;
		float density;
	};
	const Layer layers[] = {{MakeSuperellipse(0.8, 0.4, 8.0, 8.0), 1.0f},
	                        {MakeSuperellipse(0.6, 0.5, 6.0, 6.0), 2.0f},
	                        {MakeSuperellipse(0.5, 0.3, 4.0, 4.0), 0.5f},
	                        {MakeSuperellipse(0.4, 0.4, 8.0, 8.0), 3.0f},
	                        {MakeEllipse(0.6, 0.3), 1.5f}};
	b2World world(b2Vec2(0.0f, float(-kG)));
	world.SetAllowSleeping(false);
	b2Body* ground = MakeFloor(world);
	std::vector<b2Body*> bodies;
	double y = b2_polygonRadius - b2_linearSlop;
	for (const Layer& l : layers)
	{
		const double half = SupportDepth(*l.shape, 0.0, Vec2(0.0, 1.0));
		y += half;
		bodies.push_back(MakeParticle(world, l.shape, 0.0f, float(y), 0.0f, l.density, 0.6f));
		y += half - b2_linearSlop;
	}
	// Normal impulse through each contact, keyed by the upper body's index (0: the floor's).
	struct Meter : b2ContactListener
	{
		std::map<const b2Body*, int> index;
		std::vector<double> impulse;
		void PostSolve(b2Contact* contact, const b2ContactImpulse* impulses) override
		{
			const b2Body* a = contact->GetFixtureA()->GetBody();
			const b2Body* b = contact->GetFixtureB()->GetBody();
			const int ia = index.count(a) ? index[a] : -1, ib = index.count(b) ? index[b] : -1;
			const int upper = std::max(ia, ib);
			for (int32 i = 0; i < impulses->count; ++i)
				impulse[upper] += impulses->normalImpulses[i];
		}
	} meter;
	for (size_t i = 0; i < bodies.size(); ++i)
		meter.index[bodies[i]] = int(i);
	meter.index[ground] = -1;
	meter.impulse.assign(bodies.size(), 0.0);
	world.SetContactListener(&meter);
	const double dt = 1.0 / 60.0;
	const int steps = 180, averaged = 30;
	for (int i = 1; i <= steps; ++i)
	{
		if (i == steps - averaged + 1)
			std::fill(meter.impulse.begin(), meter.impulse.end(), 0.0);
		world.Step(float(dt), 8, 3);
	}
	double above = 0.0;
	for (int i = int(bodies.size()) - 1; i >= 0; --i)
	{
		above += bodies[size_t(i)]->GetMass();
		const double force = meter.impulse[size_t(i)] / (averaged * dt);
		CAPTURE(i);
		MESSAGE("stack contact under body " << i << ": force " << force << " N, weight above " << above * kG << " N");
		CHECK(force == doctest::Approx(above * kG).epsilon(0.001));
		CHECK(std::fabs(bodies[size_t(i)]->GetAngle()) < 1e-3f);
	}
}

TEST_CASE("bodies dropped on the floor bounce to e squared of the drop height")
{
	// A body falling from rest through h₀ reaches v = √(2 g h₀); Box2D's restitution sends it
	// back at e v (above its 1 m/s threshold), so it rises to e² h₀. A disc, an ellipse and a
	// blocky superellipse landing on their flat sides (one point through the centre, or two
	// with one normal), from h₀ = 1 m.
	// The height reached is read from the invariant of Box2D's free flight, not from the
	// sampled apex: with v ← v − g Δt, y ← y + v Δt every step, y + v²/(2g) − v Δt/2 is exactly
	// constant, and equals the apex of the continuous parabola. What remains is the landing
	// step: restitution acts on the velocity at the end of the step in which the body lands,
	// up to g Δt faster than at the touch, which raises the rebound height by up to
	// v Δt / h₀ ≈ 0.5 % at 960 Hz (1.9 % at 240 Hz, 7 % at 60 Hz, where the sampled apex is
	// also off by several per cent): hence 960 Hz and a 1 % tolerance.
	// The disc and the ellipse come back without spin. The block does not quite: it first
	// touches with a positive separation, where its flat face gets one manifold point (no
	// overlap, no patch), placed where the search found the face's lowest point, a millimetre
	// or two off the middle of a face that is flat to within the tolerance; the impulse there
	// spins it (rim speeds of 3–4 cm/s, whatever e). Box2D's own box gets its two corner points
	// and no spin. The bound below holds the block's rim speed under 3 % of its rebound speed.
	const ShapePtr shapes[] = {MakeCircle(0.25), MakeEllipse(0.4, 0.2), MakeSuperellipse(0.3, 0.25, 8.0, 8.0)};
	const double dt = 1.0 / 960.0;
	for (const ShapePtr& shape : shapes)
		for (double e : {0.3, 0.5, 0.7, 0.9})
		{
			CAPTURE(shape->Describe());
			CAPTURE(e);
			b2World world(b2Vec2(0.0f, float(-kG)));
			world.SetAllowSleeping(false);
			MakeFloor(world);
			const double h0 = 1.0, rest = SupportDepth(*shape, 0.0, Vec2(0.0, 1.0)) + b2_polygonRadius;
			b2Body* body = MakeParticle(world, shape, 0.0f, float(rest + h0), 0.0f, 1.0f, 0.6f, float(e));
			double h1 = 0.0, apex = 0.0, spin = 0.0;
			bool bounced = false;
			for (int i = 0; i < int(2.0 / dt); ++i)
			{
				world.Step(float(dt), 8, 3);
				const double y = body->GetPosition().y, vy = body->GetLinearVelocity().y;
				if (!bounced && vy > 0.0)
				{
					bounced = true;
					world.Step(float(dt), 8, 3); // one step clear of the floor's contact
					continue;
				}
				if (bounced)
				{
					apex = std::max(apex, y - rest);
					if (h1 == 0.0)
					{
						h1 = y + vy * vy / (2.0 * kG) - vy * dt / 2.0 - rest;
						spin = body->GetAngularVelocity();
					}
					if (vy < 0.0)
						break; // past the first apex
				}
			}
			MESSAGE(shape->Describe() << " e=" << e << ": h1/h0 = " << h1 / h0 << " (sampled apex " << apex / h0
			                          << "), e^2 = " << e * e);
			CHECK(bounced);
			CHECK(h1 / h0 == doctest::Approx(e * e).epsilon(0.01));
			CHECK(std::fabs(apex - h1) < 0.5 * e * std::sqrt(2.0 * kG * h0) * dt); // the sampled apex agrees
			const double rebound = e * std::sqrt(2.0 * kG * h0), rim = std::fabs(spin) * shape->BoundingRadius();
			MESSAGE("  rim speed " << rim << " m/s against rebound " << rebound << " m/s");
			if (shape->Describe().rfind("superellipse", 0) == 0)
				CHECK(rim < 0.03 * rebound);
			else
				CHECK(rim < 1e-4 * rebound); // straight up and down
		}
}
