// b2analytic: the analytic contacts of a step computed on several threads before b2World::Step.
#pragma once

class b2World;

namespace b2a
{

/// What PrepareContacts did.
struct PrepareContactsResult
{
	int prepared = 0; ///< contacts whose manifold was computed ahead of the step
	int threads = 1;  ///< threads allowed to compute contacts (the calling thread included)
};

/// Computes, on `threads` threads (0: std::thread::hardware_concurrency()), the manifold of every
/// existing contact that involves an analytic fixture and that the next b2World::Step will
/// evaluate first (at least one body awake), each at its bodies' current transforms. The step
/// then uses a prepared manifold only where both bodies' transforms are still bit-identical to
/// the ones it was computed at; any other evaluation (TOI sub-steps, bodies moved in between)
/// computes afresh. Each contact is computed exactly as the step would compute it, from its own
/// warm start, so a world stepped with or without preparation, on any number of threads, takes
/// bit-identical steps. Box2D itself (broad phase, solver) stays on the calling thread.
///
/// Allowed: call it right before b2World::Step on the thread that steps the world, any number
/// of times (each call recomputes). Not allowed: calling it while the world is locked (inside
/// a callback; it throws MisuseError) or while another thread touches the world or its bodies.
/// A null world or threads < 0 throw InvalidParameter naming the field. The helper threads
/// are a pool started on first use, grown to the largest `threads` - 1 asked for, and kept
/// until the program exits; the calling thread computes contacts too and waits only for those
/// a helper has begun, so a helper that is not scheduled in time costs nothing. Several threads
/// may prepare different worlds at once: the pool serves one call at a time, and a call that
/// finds it busy computes its contacts on its own thread.
PrepareContactsResult PrepareContacts(b2World* world, int threads = 0);

/// PrepareContacts(world, threads) followed by world->Step(timeStep, velocityIterations,
/// positionIterations).
PrepareContactsResult StepWithPreparedContacts(b2World* world, float timeStep, int velocityIterations, int positionIterations,
                                               int threads = 0);

} // namespace b2a
