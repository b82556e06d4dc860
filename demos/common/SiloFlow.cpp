// b2analytic demos: a silo with its discharge recycled to the top, and the particle kinds of the
// flow validations.
#include "SiloFlow.h"

#include <algorithm>
#include <cmath>

namespace b2a::demo
{

namespace
{
// Area of |x/a|^n + |y/b|^n <= 1: 4ab Γ(1 + 1/n)² / Γ(1 + 2/n).
double SuperellipseArea(double a, double b, double n)
{
	return 4.0 * a * b * std::tgamma(1.0 + 1.0 / n) * std::tgamma(1.0 + 1.0 / n) / std::tgamma(1.0 + 2.0 / n);
}

// Mean of s² for s uniform in [1 - spread, 1 + spread].
double MeanSquareScale(double spread)
{
	return 1.0 + spread * spread / 3.0;
}
} // namespace

bool MakeParticleKind(const std::string& name, ParticleKind& kind)
{
	kind.name = name;
	kind.config = BeverlooEllipses(); // friction 0.5 on particles, floor and walls; ±5 %
	GranularConfig& c = kind.config;
	if (name == "ellipse")
	{
		kind.d = c.width;
	}
	else if (name == "disk")
	{
		// The ellipses' area π a b, as a disk: diameter 2 √(a b).
		const double a = 0.5 * c.width, b = a / c.aspect;
		c.width = 2.0 * std::sqrt(a * b);
		c.aspect = 1.0;
		kind.d = c.width;
	}
	else if (name == "superellipse")
	{
		const GranularConfig hopper; // the hopper demo's particles
		c.exponent = hopper.exponent;
		c.width = hopper.width;
		c.aspect = hopper.aspect;
		c.sizeSpread = hopper.sizeSpread;
		kind.d = c.width;
	}
	else
		return false;
	const double a = 0.5 * c.width, b = a / c.aspect;
	kind.area = SuperellipseArea(a, b, c.exponent) * MeanSquareScale(c.sizeSpread);
	return true;
}

int ParticlesForBed(const ParticleKind& kind, double width, double height, double fraction)
{
	return std::max(10, int(std::lround(width * height * fraction / kind.area)));
}

std::vector<ParticleState> SettleBed(const GranularConfig& config, double minTime, double maxTime, double ratio, double& fraction,
                                     double& depth)
{
	GranularScene scene(config);
	const Energies e0 = scene.ComputeEnergies();
	int step = 0;
	while (scene.Time() < maxTime)
	{
		scene.Step();
		if (++step % 100 == 0 && scene.Time() > minTime)
		{
			const Energies e = scene.ComputeEnergies();
			if (e.translational + e.rotational < ratio * (e0.Total() - e.potential))
				break;
		}
	}
	fraction = scene.PackingFraction();
	depth = scene.PileHeight();
	return scene.SaveState();
}

bool IsFree(b2World& world, const b2Body* self, b2Vec2 c, float r)
{
	struct Query : b2QueryCallback
	{
		const b2Body* self = nullptr;
		bool hit = false;
		bool ReportFixture(b2Fixture* f) override
		{
			if (f->GetBody() == self || f->GetBody()->GetType() != b2_dynamicBody || !f->GetBody()->IsEnabled())
				return true;
			hit = true;
			return false;
		}
	} query;
	query.self = self;
	b2AABB box;
	box.lowerBound = c - b2Vec2(r, r);
	box.upperBound = c + b2Vec2(r, r);
	world.QueryAABB(&query, box);
	return !query.hit;
}

bool PlaceInFreeSpot(b2World& world, b2Body* body, double x0, double x1, double y0, double y1, int attempts, std::mt19937_64& rng,
                     long& retries)
{
	std::uniform_real_distribution<double> U(0.0, 1.0);
	const float r = float(GetAnalyticShape(body->GetFixtureList())->BoundingRadius() + 0.2);
	for (int attempt = 0; attempt < attempts; ++attempt)
	{
		const double ux = U(rng), uy = U(rng);
		const b2Vec2 c(float(x0 + r + (x1 - x0 - 2.0 * r) * ux), float(y0 + (y1 - y0) * uy));
		if (!IsFree(world, body, c, r))
		{
			++retries;
			continue;
		}
		body->SetTransform(c, body->GetAngle());
		body->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
		body->SetAngularVelocity(0.0f);
		return true;
	}
	return false;
}

RecyclingSilo::RecyclingSilo(const GranularConfig& config, const std::vector<ParticleState>& packing, double bandLow, double bandHigh,
                             std::uint64_t seed)
	: m_scene(config, packing), m_bandLow(bandLow), m_bandHigh(bandHigh), m_rng(seed * 7919u + 17u)
{
}

bool RecyclingSilo::Recycle(b2Body* body)
{
	const double w = 0.5 * m_scene.Config().boxWidth;
	body->SetEnabled(true);
	if (PlaceInFreeSpot(m_scene.World(), body, -w, w, m_bandLow, m_bandHigh, 20, m_rng, m_retries))
		return true;
	// No room this step: park it, disabled, above the container, and try again next step.
	body->SetEnabled(false);
	body->SetTransform(b2Vec2(0.0f, float(m_scene.Config().boxHeight + 100.0)), body->GetAngle());
	body->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
	body->SetAngularVelocity(0.0f);
	m_waiting.push_back(body);
	return false;
}

int RecyclingSilo::Step()
{
	m_scene.Step();
	std::vector<b2Body*> waiting;
	waiting.swap(m_waiting);
	for (b2Body* b : waiting)
		Recycle(b);
	const double below = -m_scene.Config().width;
	int exits = 0;
	for (b2Body* b = m_scene.World().GetBodyList(); b; b = b->GetNext())
		if (b->GetType() == b2_dynamicBody && b->IsEnabled() && b->GetPosition().y < below)
		{
			++exits;
			Recycle(b);
		}
	m_exits += exits;
	return exits;
}

int RecyclingSilo::ClearOutlet(double height)
{
	const double half = 0.5 * m_scene.Config().outletWidth + m_scene.Config().width;
	std::vector<b2Body*> over;
	for (b2Body* b = m_scene.World().GetBodyList(); b; b = b->GetNext())
	{
		const b2Vec2 p = b->GetPosition();
		if (b->GetType() == b2_dynamicBody && b->IsEnabled() && std::fabs(p.x) < half && p.y < height)
			over.push_back(b);
	}
	for (b2Body* b : over)
		Recycle(b);
	return int(over.size());
}

} // namespace b2a::demo
