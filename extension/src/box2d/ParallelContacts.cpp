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
#include <condition_variable>
#include <cstdint>
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
// One batch of contacts split into chunks. It lives on the calling thread's stack; a worker
// touches it only after claiming one of its chunks, and the caller returns only once every
// claimed chunk is done.
struct Batch
{
	AnalyticContact* const* work = nullptr;
	int count = 0;
	int chunk = 1;
	std::atomic<bool> failed{false};
	std::mutex errorMutex;
	std::exception_ptr error;

	void Run(int k)
	{
		if (failed.load(std::memory_order_relaxed))
			return; // another chunk threw: the batch is abandoned, the claim still counts as done
		try
		{
			const int end = std::min(count, (k + 1) * chunk);
			for (int i = k * chunk; i < end; ++i)
				work[i]->Prepare();
		}
		catch (...)
		{
			std::lock_guard<std::mutex> lock(errorMutex);
			if (!error)
				error = std::current_exception();
			failed.store(true, std::memory_order_relaxed);
		}
	}
};

// Worker threads started once and kept for the process. A batch's chunks are claimed through
// one atomic ticket, the batch's generation in the high 32 bits and the next chunk in the low
// ones, so a worker that wakes late for a finished batch sees another generation (or no chunk
// left) and claims nothing. The caller claims chunks too and then waits only for the chunks
// workers have claimed: a worker that was never scheduled costs the caller nothing (the
// threads it started and joined every step before waited for exactly that).
class WorkerPool
{
public:
	~WorkerPool()
	{
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			m_stopping = true;
		}
		m_wake.notify_all();
		for (std::thread& t : m_workers)
			t.join();
	}

	// Runs every chunk of `batch` with up to `helpers` workers beside the calling thread. One
	// batch at a time: a second thread calling meanwhile (another world) runs its batch alone.
	void Run(Batch& batch, int chunks, int helpers)
	{
		std::unique_lock<std::mutex> busy(m_busy, std::try_to_lock);
		if (!busy.owns_lock())
		{
			for (int k = 0; k < chunks; ++k)
				batch.Run(k);
			return;
		}
		std::uint32_t generation;
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			while (int(m_workers.size()) < helpers)
				m_workers.emplace_back([this] { Work(); });
			generation = ++m_generation;
			m_batch = &batch;
			m_chunks = chunks;
			m_seats = helpers;
			m_workerDone = 0;
			m_ticket.store(std::uint64_t(generation) << 32, std::memory_order_release);
		}
		m_wake.notify_all();
		const int own = Claim(batch, generation, chunks, false);
		std::unique_lock<std::mutex> lock(m_mutex);
		m_seats = 0; // a worker waking from now on finds the batch over and sleeps again
		m_batch = nullptr;
		m_done.wait(lock, [&] { return m_workerDone == chunks - own; });
	}

private:
	// Claims and runs chunks of the batch of `generation` until none is left; returns how many.
	int Claim(Batch& batch, std::uint32_t generation, int chunks, bool worker)
	{
		int ran = 0;
		std::uint64_t ticket = m_ticket.load(std::memory_order_acquire);
		for (;;)
		{
			const int k = int(ticket & 0xffffffffu);
			if (std::uint32_t(ticket >> 32) != generation || k >= chunks)
				return ran;
			if (!m_ticket.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel, std::memory_order_acquire))
				continue; // another thread claimed first; `ticket` holds the current value
			batch.Run(k);
			++ran;
			if (worker)
			{
				{
					std::lock_guard<std::mutex> lock(m_mutex);
					++m_workerDone;
				}
				m_done.notify_one();
			}
			ticket = m_ticket.load(std::memory_order_acquire);
		}
	}

	void Work()
	{
		std::uint32_t seen = 0;
		std::unique_lock<std::mutex> lock(m_mutex);
		for (;;)
		{
			m_wake.wait(lock, [&] { return m_stopping || (m_generation != seen && m_seats > 0); });
			if (m_stopping)
				return;
			seen = m_generation;
			--m_seats;
			Batch& batch = *m_batch;
			const int chunks = m_chunks;
			lock.unlock();
			Claim(batch, seen, chunks, true);
			lock.lock();
		}
	}

	std::mutex m_busy;  // held by the caller whose batch the workers serve
	std::mutex m_mutex; // guards everything below but the ticket
	std::condition_variable m_wake, m_done;
	std::vector<std::thread> m_workers;
	std::atomic<std::uint64_t> m_ticket{0};
	std::uint32_t m_generation = 0;
	Batch* m_batch = nullptr;
	int m_chunks = 0, m_seats = 0, m_workerDone = 0;
	bool m_stopping = false;
};

WorkerPool& Pool()
{
	static WorkerPool pool; // started on first use, joined at exit
	return pool;
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
	// pair costs a hundred ellipse pairs), large enough that the ticket is not contended. Which
	// thread computes a contact does not change its result.
	Batch batch;
	batch.work = work.data();
	batch.count = result.prepared;
	batch.chunk = 16;
	const int chunks = (result.prepared + batch.chunk - 1) / batch.chunk;
	result.threads = std::max(1, std::min(threads, chunks));
	if (result.threads == 1)
		for (int k = 0; k < chunks; ++k)
			batch.Run(k);
	else
		Pool().Run(batch, chunks, result.threads - 1);
	if (batch.error)
		std::rethrow_exception(batch.error);
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
