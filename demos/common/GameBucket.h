// The bucket scene in a game's units (metres, g = 10 m/s^2, 60 Hz, 8 velocity and 3 position
// iterations, sleeping on): particles dropped from a lattice into a b2ChainShape bucket, with
// analytic fixtures or with Box2D 8-gons inscribed in the same shapes. Shared by b2a_demo_game
// and b2a_bench_scenes --game.
#pragma once

#include "b2analytic/Shape.h"

#include <box2d/box2d.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace b2a::demo
{
/// Gravity of the game scenes (m/s^2).
inline const b2Vec2 kGameGravity(0.0f, -10.0f);
/// Step of the game scenes (s): Box2D's testbed 60 Hz.
constexpr float kGameStep = 1.0f / 60.0f;
/// Velocity and position iterations of the game scenes (Box2D's testbed).
constexpr int kGameVelocityIterations = 8, kGamePositionIterations = 3;

/// The bucket's families by name: "ellipse" (0.5 x 0.3 m), "superellipse" (n = 4, 0.5 x 0.3 m),
/// "heart" (alpha 0.2), "circle" (radius 0.4 m), or "mixed" (the four, in that order).
std::vector<ShapePtr> GameFamilies(const std::string& family);

/// The family names GameFamilies takes, "mixed" last.
const std::vector<std::string>& GameFamilyNames();

/// A world with a chain bucket `width` m wide and 40 m tall, taller as width / 16 m where wider
/// (its links face inwards, friction 0.6) and `particles` bodies on a lattice of cells two bounding radii and 5 cm wide above its
/// floor, the families in turn, at random angles (from `seed`): analytic fixtures, or with
/// `polygons` the Box2D 8-gons inscribed in the same shapes (b2a::MakeInscribedPolygon: for a
/// heart, the convex hull of 8 points of its outline); density 1, friction 0.6.
std::unique_ptr<b2World> MakeGameBucket(const std::vector<ShapePtr>& families, int particles, bool polygons, std::uint64_t seed,
                                        double width = 16.0);

/// True when every dynamic body of the world sleeps.
bool AllAsleep(b2World& world);

/// Dynamic bodies awake.
int AwakeBodies(b2World& world);

} // namespace b2a::demo
