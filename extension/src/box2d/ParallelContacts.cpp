// b2analytic: the analytic contacts of a step computed on several threads before b2World::Step.
#include "b2analytic/ParallelContacts.h"
#include "b2analytic/AnalyticFixture.h"

#include "box2d/AnalyticContact.h"

#include <box2d/b2_body.h>
#include <box2d/b2_broad_phase.h>
#include <box2d/b2_contact_manager.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace b2a
{

namespace
{
// b2Fixture keeps its broad-phase proxies protected; a pointer to the member taken through a
// derived class reads them without changing Box2D.
struct FixtureProxies : b2Fixture
{
	static const b2FixtureProxy& Of(const b2Fixture* f, int child) { return (f->*(&FixtureProxies::m_proxies))[child]; }
};

// Contacts b2ContactManager::Collide will evaluate: Box2D skips a pair when neither body is
// awake and dynamic or kinematic, destroys it when the fat AABBs of the broad phase no longer
// overlap, and sensors only test overlap (no Evaluate).
bool StepEvaluates(const b2BroadPhase& broadPhase, b2Contact* c)
{
	const b2Fixture* fa = c->GetFixtureA();
	const b2Fixture* fb = c->GetFixtureB();
	if (fa->IsSensor() || fb->IsSensor())
		return false;
	const b2Body* ba = fa->GetBody();
	const b2Body* bb = fb->GetBody();
	const bool activeA = ba->IsAwake() && ba->GetType() != b2_staticBody;
	const bool activeB = bb->IsAwake() && bb->GetType() != b2_staticBody;
	if (!activeA && !activeB)
		return false;
	return broadPhase.TestOverlap(FixtureProxies::Of(fa, c->GetChildIndexA()).proxyId,
	                              FixtureProxies::Of(fb, c->GetChildIndexB()).proxyId);
}
} // namespace

PrepareContactsResult PrepareContacts(b2World* world, int threads)
{
	if (!world)
		throw InvalidParameter("PrepareContacts: field 'world' is null", "world");
	if (world->IsLocked())
		throw MisuseError("PrepareContacts: the world is locked (inside Step or a world callback); prepare before Step");
	if (threads < 0)
		throw InvalidParameter("PrepareContacts", "threads", "must be >= 0 (0: one per hardware thread)", threads);
	if (threads == 0)
		threads = int(std::max(1u, std::thread::hardware_concurrency()));

	std::vector<AnalyticContact*> work;
	for (b2Contact* c = world->GetContactList(); c; c = c->GetNext())
		if (AnalyticContact* ac = AnalyticContact::FromAnalytic(c))
			if (StepEvaluates(world->GetContactManager().m_broadPhase, c))
				work.push_back(ac);

	PrepareContactsResult result;
	result.prepared = int(work.size());
	// Chunks of contacts handed out in list order: small enough to balance the load (a heart
	// pair costs a hundred ellipse pairs), large enough that the counter is not contended. Which
	// thread computes a contact does not change its result.
	const int chunk = 16;
	const int chunks = (result.prepared + chunk - 1) / chunk;
	result.threads = std::max(1, std::min(threads, chunks));
	std::atomic<int> next{0};
	std::exception_ptr error;
	std::mutex errorMutex;
	auto run = [&] {
		try
		{
			for (int k = next.fetch_add(1); k < chunks; k = next.fetch_add(1))
			{
				const int end = std::min(result.prepared, (k + 1) * chunk);
				for (int i = k * chunk; i < end; ++i)
					work[i]->Prepare();
			}
		}
		catch (...)
		{
			std::lock_guard<std::mutex> lock(errorMutex);
			if (!error)
				error = std::current_exception();
			next.store(chunks); // the others stop at their next chunk
		}
	};
	std::vector<std::thread> helpers;
	helpers.reserve(result.threads - 1);
	for (int t = 1; t < result.threads; ++t)
		helpers.emplace_back(run);
	run();
	for (std::thread& h : helpers)
		h.join();
	if (error)
		std::rethrow_exception(error);
	return result;
}

PrepareContactsResult StepWithPreparedContacts(b2World* world, float timeStep, int velocityIterations, int positionIterations,
                                               int threads)
{
	const PrepareContactsResult result = PrepareContacts(world, threads);
	world->Step(timeStep, velocityIterations, positionIterations);
	return result;
}

} // namespace b2a
