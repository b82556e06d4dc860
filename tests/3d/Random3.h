// b2analytic 3D tests: random directions and rotations.
#pragma once

#include "b2analytic/3d/Math3.h"
#include "TestSupport.h"

namespace b2a::test
{

/// A direction uniform on the sphere (rejection from the cube).
inline Vec3 RandomUnit(Random& rng)
{
	for (;;)
	{
		const Vec3 v(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
		if (LengthSquared(v) > 0.01 && LengthSquared(v) <= 1.0)
			return Normalize(v);
	}
}

/// A random rotation (a normalised random quaternion).
inline Quat RandomRotation(Random& rng)
{
	return Normalize(Quat(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)));
}

} // namespace b2a::test
