// b2a_viewer: analytic particles (superellipses, ellipses, hearts) among Box2D's own shapes:
// boxes, circles, an edge ramp and a chain bowl. Every pair type meets every other.
#include "samples/Samples.h"

#include "b2analytic/HeartShape.h"
#include "b2analytic/SuperellipseShape.h"

#include <cmath>

namespace b2a::viewer
{
namespace
{
class MixedScene : public Sample
{
public:
	MixedScene()
	{
		MakeWorld(b2Vec2(0.0f, -10.0f));
		// A chain bowl, open at the top. Box2D's chains collide on the right of their direction
		// only, so the bowl runs from its right rim to its left.
		b2Vec2 bowl[25];
		for (int i = 0; i < 25; ++i)
		{
			const float t = b2_pi * (1.95f - 0.9f * float(i) / 24.0f);
			bowl[i] = b2Vec2(18.0f * std::cos(t), 16.0f + 16.0f * std::sin(t));
		}
		b2ChainShape chain;
		chain.CreateChain(bowl, 25, bowl[0], bowl[24]);
		b2FixtureDef cf;
		cf.shape = &chain;
		cf.friction = 0.6f;
		GroundBody()->CreateFixture(&cf);
		// Two edge ramps that feed it.
		AddGroundEdge(b2Vec2(-22.0f, 30.0f), b2Vec2(-12.5f, 27.0f));
		AddGroundEdge(b2Vec2(22.0f, 32.0f), b2Vec2(12.5f, 29.0f));

		const ShapePtr shapes[] = {MakeSuperellipse(0.7, 0.45, 6.0, 6.0), MakeEllipse(0.8, 0.4), MakeHeart(0.5),
		                           MakeSuperellipse(0.6, 0.6, 3.0, 3.0), MakeSuperellipse(0.5, 0.9, 1.5, 1.5)};
		b2PolygonShape box;
		box.SetAsBox(0.5f, 0.35f);
		b2CircleShape circle;
		circle.m_radius = 0.5f;
		for (int row = 0; row < 8; ++row)
			for (int col = 0; col < 8; ++col)
			{
				const b2Vec2 p(-10.5f + 3.0f * float(col) + 0.3f * float(row % 2), 8.0f + 2.2f * float(row));
				const float angle = 0.37f * float(row * 8 + col);
				const int kind = (row * 8 + col) % 7;
				if (kind < 5)
				{
					AddParticle(shapes[kind], p, angle);
					continue;
				}
				b2BodyDef bd;
				bd.type = b2_dynamicBody;
				bd.position = p;
				bd.angle = angle;
				b2FixtureDef fd;
				fd.shape = kind == 5 ? static_cast<b2Shape*>(&box) : static_cast<b2Shape*>(&circle);
				fd.density = 1.0f;
				fd.friction = 0.6f;
				World()->CreateBody(&bd)->CreateFixture(&fd);
			}
	}

	SampleDefaults Defaults() const override
	{
		return MetreScene(b2Vec2(-21.0f, -1.0f), b2Vec2(21.0f, 33.0f));
	}
};
} // namespace

std::unique_ptr<Sample> MakeMixedSample()
{
	return std::make_unique<MixedScene>();
}

} // namespace b2a::viewer
