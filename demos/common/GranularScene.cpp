// b2analytic demos: the granular scene shared by the packing and hopper demos.
#include "GranularScene.h"

#include "Svg.h"

#include "b2analytic/ParallelContacts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace b2a::demo
{

// Sums the vertical normal impulses on the floor and gate fixtures.
struct GranularScene::FloorMeter : b2ContactListener
{
	std::vector<const b2Fixture*> floor;
	double impulse = 0.0;
	void PostSolve(b2Contact* contact, const b2ContactImpulse* impulses) override
	{
		const b2Fixture* a = contact->GetFixtureA();
		const b2Fixture* b = contact->GetFixtureB();
		if (std::find(floor.begin(), floor.end(), a) == floor.end() && std::find(floor.begin(), floor.end(), b) == floor.end())
			return;
		b2WorldManifold wm;
		contact->GetWorldManifold(&wm);
		for (int32 i = 0; i < impulses->count; ++i)
			impulse += impulses->normalImpulses[i] * std::fabs(wm.normal.y);
	}
};

ShapePtr MixedParticle(double a, double b, double kind, double exponent)
{
	// 2 % hearts, 30 % circles, 30 % ellipses, 38 % superellipses with n in [2.5, 5.5).
	if (kind < 0.02)
	{
		// A heart about as wide as the others are long: the heart of α = 1 is 2.278 wide and
		// 2.237 tall (its tight box), and near α = 1 its extents grow about as √α (the equation
		// is not homogeneous, so its outline changes a little with α: within 0.5 % of 2a here).
		const double s = 2.0 * a / 2.278;
		return MakeHeart(s * s);
	}
	if (kind < 0.32)
		return MakeCircle(0.5 * (a + b));
	if (kind < 0.62)
		return MakeEllipse(a, b);
	const double n = 2.5 + 3.0 * exponent;
	return MakeSuperellipse(a, b, n, n);
}

GranularScene::GranularScene(const GranularConfig& c) : m_config(c)
{
	BuildContainer(true);
	// Particles: superellipses of random size (±spread) and orientation on a jittered lattice.
	std::mt19937_64 rng(c.seed);
	std::uniform_real_distribution<double> U(0.0, 1.0);
	const double a0 = 0.5 * c.width, cell = 1.15 * c.width;
	const int perRow = std::max(1, int((c.boxWidth - c.width) / cell));
	for (int i = 0; i < c.particles; ++i)
	{
		const double s = 1.0 + c.sizeSpread * (2.0 * U(rng) - 1.0);
		const double a = a0 * s, b = a / c.aspect;
		ShapePtr shape = c.mixed               ? MixedParticle(a, b, U(rng), U(rng))
		                 : c.exponent != 2.0 ? ShapePtr(MakeSuperellipse(a, b, c.exponent, c.exponent))
		                 : c.aspect == 1.0  ? ShapePtr(MakeCircle(a))
		                                    : ShapePtr(MakeEllipse(a, b));
		const int row = i / perRow, col = i % perRow;
		const double x = -0.5 * (perRow - 1) * cell + col * cell + 0.1 * c.width * (U(rng) - 0.5);
		const double y = c.width + row * cell + 0.1 * c.width * U(rng);
		AddParticle(shape, Pose(Vec2(x, y), 2.0 * kPi * U(rng)));
	}
}

GranularScene::GranularScene(const GranularConfig& c, const std::vector<ParticleState>& packing) : m_config(c)
{
	BuildContainer(false);
	for (const ParticleState& p : packing)
		AddParticle(p.shape, p.pose);
}

void GranularScene::BuildContainer(bool gate)
{
	const GranularConfig& c = m_config;
	m_world = std::make_unique<b2World>(b2Vec2(0.0f, float(-c.gravity)));
	m_world->SetAllowSleeping(false);
	m_meter = std::make_unique<FloorMeter>();
	m_world->SetContactListener(m_meter.get());

	// Container: static edges. Box2D mixes restitution thresholds by their minimum, so the
	// walls get the raised millimetre threshold as well.
	b2BodyDef bd;
	m_container = m_world->CreateBody(&bd);
	b2EdgeShape edge;
	b2FixtureDef fd;
	fd.shape = &edge;
	fd.restitutionThreshold = 1000.0f; // mm/s
	const float w = float(0.5 * c.boxWidth), h = float(c.boxHeight), o = float(0.5 * c.outletWidth);
	fd.friction = float(c.wallFriction);
	edge.SetTwoSided(b2Vec2(-w, 0.0f), b2Vec2(-w, h));
	m_container->CreateFixture(&fd);
	edge.SetTwoSided(b2Vec2(w, 0.0f), b2Vec2(w, h));
	m_container->CreateFixture(&fd);
	fd.friction = float(c.friction);
	if (o > 0.0f)
	{
		edge.SetTwoSided(b2Vec2(-w, 0.0f), b2Vec2(-o, 0.0f));
		m_meter->floor.push_back(m_container->CreateFixture(&fd));
		edge.SetTwoSided(b2Vec2(o, 0.0f), b2Vec2(w, 0.0f));
		m_meter->floor.push_back(m_container->CreateFixture(&fd));
		if (gate)
		{
			edge.SetTwoSided(b2Vec2(-o, 0.0f), b2Vec2(o, 0.0f));
			m_gate = m_container->CreateFixture(&fd);
			m_meter->floor.push_back(m_gate);
		}
	}
	else
	{
		edge.SetTwoSided(b2Vec2(-w, 0.0f), b2Vec2(w, 0.0f)); // no outlet: one closed floor
		m_meter->floor.push_back(m_container->CreateFixture(&fd));
	}
}

void GranularScene::AddParticle(ShapePtr shape, const Pose& pose)
{
	const GranularConfig& c = m_config;
	b2BodyDef pd;
	pd.type = b2_dynamicBody;
	pd.position.Set(float(pose.p.x), float(pose.p.y));
	pd.angle = float(pose.q.Angle());
	b2Body* body = m_world->CreateBody(&pd);
	b2FixtureDef pf;
	pf.density = float(c.density);
	pf.friction = float(c.friction);
	pf.restitution = float(c.restitution);
	pf.restitutionThreshold = 1000.0f;
	if (c.polygonVertices > 0)
	{
		const b2PolygonShape polygon = MakeInscribedPolygon(*shape, c.polygonVertices);
		pf.shape = &polygon;
		body->CreateFixture(&pf);
	}
	else
	{
		AnalyticFixtureDef af;
		af.shape = shape;
		CreateAnalyticFixture(body, pf, af);
	}
	m_shapes.push_back(std::move(shape));
	m_particles.push_back(body);
}

GranularConfig BeverlooEllipses()
{
	GranularConfig c;
	c.exponent = 2.0;      // ellipses
	c.width = 2.0;         // major axis d (mm)
	c.aspect = 2.0 / 0.66; // minor axis 0.66 mm
	c.sizeSpread = 0.05;
	c.friction = 0.5;
	c.wallFriction = 0.5;
	return c;
}

Pose GranularScene::ParticlePose(size_t i) const
{
	const b2Fixture* f = m_particles[i]->GetFixtureList();
	if (GetAnalyticShape(f))
		return GetAnalyticPose(f);
	const b2Transform& xf = m_particles[i]->GetTransform(); // a polygon particle: shape frame = body frame
	Rot q;
	q.c = xf.q.c;
	q.s = xf.q.s;
	return Pose(Vec2(xf.p.x, xf.p.y), q);
}

std::vector<Vec2> GranularScene::ParticleOutline(size_t i) const
{
	const b2Fixture* f = m_particles[i]->GetFixtureList();
	if (GetAnalyticShape(f))
		return Outline(*m_shapes[i], GetAnalyticPose(f), 0.0 / 0.0, 20);
	const b2PolygonShape* polygon = static_cast<const b2PolygonShape*>(f->GetShape());
	std::vector<Vec2> outline;
	for (int32 k = 0; k < polygon->m_count; ++k)
	{
		const b2Vec2 v = b2Mul(m_particles[i]->GetTransform(), polygon->m_vertices[k]);
		outline.push_back(Vec2(v.x, v.y));
	}
	return outline;
}

std::vector<ParticleState> GranularScene::SaveState() const
{
	std::vector<ParticleState> out;
	for (size_t i = 0; i < m_particles.size(); ++i)
		out.push_back({m_shapes[i], ParticlePose(i)});
	return out;
}

double GranularScene::MeanParticleMass() const
{
	double m = 0.0;
	for (const b2Body* b : m_particles)
		m += b->GetMass();
	return m_particles.empty() ? 0.0 : m / double(m_particles.size());
}

GranularScene::~GranularScene() = default;

Json GranularScene::SummaryHead(const std::string& demo, const DemoOptions& options) const
{
	const GranularConfig& c = m_config;
	Json j;
	j["demo"] = demo;
	j["quick"] = options.quick;
	j["seed"] = options.seed;
	j["particles"] = c.particles;
	j["particle"] = {{"shape", c.exponent != 2.0 ? "superellipse" : c.aspect == 1.0 ? "disk" : "ellipse"}, {"exponent", c.exponent}, {"mean_width_mm", c.width},
	                 {"aspect", c.aspect}, {"size_spread", c.sizeSpread}};
	if (c.polygonVertices > 0)
		j["particle"]["box2d_polygon_vertices"] = c.polygonVertices;
	j["box_width_mm"] = c.boxWidth;
	j["time_step_s"] = c.dt;
	j["contact_threads"] = c.threads;
	return j;
}

void GranularScene::Step()
{
	Step(m_config.dt, m_config.velocityIterations, m_config.positionIterations);
}

void GranularScene::Step(double dt, int velocityIterations, int positionIterations)
{
	if (m_config.threads > 1)
		StepWithPreparedContacts(m_world.get(), float(dt), velocityIterations, positionIterations, m_config.threads);
	else
		m_world->Step(float(dt), velocityIterations, positionIterations);
	m_time += dt;
	++m_meterSteps;
	// Particles that fell well below the outlet have left: count and remove them.
	const double below = -2.0 * m_config.width;
	for (size_t i = 0; i < m_particles.size();)
	{
		if (m_particles[i]->GetPosition().y < below)
		{
			m_world->DestroyBody(m_particles[i]);
			m_particles[i] = m_particles.back();
			m_particles.pop_back();
			m_shapes[i] = m_shapes.back();
			m_shapes.pop_back();
			++m_discharged;
		}
		else
			++i;
	}
}

Energies GranularScene::ComputeEnergies() const
{
	Energies e;
	for (const b2Body* b : m_particles)
	{
		const b2Vec2 v = b->GetLinearVelocity();
		const double w = b->GetAngularVelocity();
		const double Ic = b->GetInertia() - b->GetMass() * b2Dot(b->GetLocalCenter(), b->GetLocalCenter());
		e.translational += 0.5 * b->GetMass() * b2Dot(v, v);
		e.rotational += 0.5 * Ic * w * w;
		e.potential += b->GetMass() * m_config.gravity * b->GetWorldCenter().y;
	}
	return e;
}

double GranularScene::TakeBottomForce()
{
	const double force = m_meterSteps > 0 ? m_meter->impulse / (m_meterSteps * m_config.dt) : 0.0;
	m_meter->impulse = 0.0;
	m_meterSteps = 0;
	return force;
}

double GranularScene::Weight() const
{
	double w = 0.0;
	for (const b2Body* b : m_particles)
		w += b->GetMass() * m_config.gravity;
	return w;
}

void GranularScene::OpenOutlet()
{
	if (!m_gate)
		return;
	m_meter->floor.erase(std::find(m_meter->floor.begin(), m_meter->floor.end(), m_gate));
	m_container->DestroyFixture(m_gate);
	m_gate = nullptr;
}

double GranularScene::PileHeight() const
{
	double h = 0.0;
	for (const b2Body* b : m_particles)
		h = std::max(h, double(b->GetPosition().y));
	return h;
}

double GranularScene::PackingFraction() const
{
	const double cut = 0.8 * PileHeight();
	if (!(cut > 0.0))
		return 0.0;
	double area = 0.0;
	for (size_t i = 0; i < m_particles.size(); ++i)
		if (m_particles[i]->GetPosition().y < cut && m_particles[i]->GetPosition().y > 0.0)
			area += m_shapes[i]->Mass().area;
	return area / (m_config.boxWidth * cut);
}

double GranularScene::KineticEnergyNearOutlet(double radius) const
{
	double e = 0.0;
	for (const b2Body* b : m_particles)
		if (b2Distance(b->GetPosition(), b2Vec2(0.0f, 0.0f)) < radius)
			e += 0.5 * b->GetMass() * b2Dot(b->GetLinearVelocity(), b->GetLinearVelocity());
	return e;
}

int GranularScene::ParticlesOverOutlet(double height) const
{
	int n = 0;
	for (const b2Body* b : m_particles)
		if (std::fabs(b->GetPosition().x) < 0.5 * m_config.outletWidth && b->GetPosition().y > 0.0 && b->GetPosition().y < height)
			++n;
	return n;
}

void GranularScene::WriteSnapshot(const std::string& path, const std::string& title, double timeOrigin,
                                  const std::string& clockNote) const
{
	const double moving = 5.0; // mm/s: faster particles are drawn as moving
	const Style rest{palette::blue, "#1f1f1f", 0.4, "", 0.85}, move{palette::orange, "#1f1f1f", 0.4, "", 0.85};
	const Style wall{"none", "#333333", 3.0, "", 1.0}, gate{"none", palette::vermillion, 3.0, "", 1.0};
	std::vector<KeyEntry> key = {{KeyEntry::Kind::area, rest, "at rest (below 5 mm/s)"},
	                             {KeyEntry::Kind::area, move, "moving"},
	                             {KeyEntry::Kind::line, wall, "walls and floor"}};
	if (m_gate)
		key.push_back({KeyEntry::Kind::line, gate, "gate over the outlet (closed)"});
	// The picture: the container from below the floor (where discharged particles fall) to above
	// the pile, and a band on top for the title and the key, beside each other.
	const double w = 0.5 * m_config.boxWidth, pixelWidth = 720.0;
	const double top = std::max(PileHeight() + 2.0 * m_config.width, 0.3 * m_config.boxWidth);
	const double bottom = -3.0 * m_config.width;
	const double perMm = pixelWidth / (2.0 * w + 4.0);
	const double band = std::max(70.0, SvgCanvas::KeySize(key).y + 14.0) / perMm;
	SvgCanvas svg(Vec2(-w - 2.0, bottom), Vec2(w + 2.0, top + band), pixelWidth);
	const double o = 0.5 * m_config.outletWidth;
	for (size_t i = 0; i < m_particles.size(); ++i)
		svg.Polygon(ParticleOutline(i), m_particles[i]->GetLinearVelocity().Length() > moving ? move : rest);
	svg.Polyline({Vec2(-w, top), Vec2(-w, 0.0), Vec2(-o, 0.0)}, wall); // over the particles that touch them
	svg.Polyline({Vec2(o, 0.0), Vec2(w, 0.0), Vec2(w, top)}, wall);
	if (m_gate)
		svg.Polyline({Vec2(-o, 0.0), Vec2(o, 0.0)}, gate);

	// One clock: the scene's time from `timeOrigin`, as the caller names it.
	char clock[160];
	std::snprintf(clock, sizeof(clock), "t = %.3f s%s%s", m_time - timeOrigin, clockNote.empty() ? "" : " ", clockNote.c_str());
	std::string counts = std::to_string(Remaining()) + " particles in the container";
	if (m_discharged > 0 || (m_config.outletWidth > 0.0 && !m_gate)) // an outlet, open
		counts += ", " + std::to_string(m_discharged) + " discharged";
	svg.Label(10, 22, title, 15);
	svg.Label(10, 42, clock, 13);
	svg.Label(10, 60, counts, 12);
	svg.Key(svg.Width() - SvgCanvas::KeySize(key).x - 8.0, 6.0, key);
	// A scale bar under the right-hand floor, where nothing falls.
	const double length = RoundLength(0.25 * m_config.boxWidth);
	svg.ScaleBar(svg.PixelOf(Vec2(w - length, 0.0)).x, svg.Height() - 10.0, length, LengthLabel(length, "mm"));
	WriteText(path, svg.Finish());
}

} // namespace b2a::demo
