// b2analytic: the registry of shape kinds.
#include "b2analytic/ShapeKind.h"

#include "b2analytic/Shape.h"
#include "b2analytic/3d/ShapeKind3.h"

#include <atomic>
#include <mutex>

namespace b2a
{

namespace
{
// The kinds registered so far. An entry is written once, under the mutex, before `count` makes
// it visible, and never changed: readers (the dispatch tables' default cells, on every contact
// of a kind nobody registered a function for) need no lock.
struct Registry
{
	std::mutex mutex;
	std::string name[ShapeKind::kMaxKinds];
	int dimension[ShapeKind::kMaxKinds] = {};
	SolverClass solverClass[ShapeKind::kMaxKinds] = {};
	std::atomic<int> count{0};

	Registry()
	{
		// The built-in kinds, with the ids BuiltinKinds promises.
		for (int i = 0; i < BuiltinKinds::count; ++i)
			Add(BuiltinKinds::names[i], 2, BuiltinKinds::solverClasses[i]);
		for (int i = 0; i < BuiltinKinds3::count; ++i)
			Add(BuiltinKinds3::names[i], 3, BuiltinKinds3::solverClasses[i]);
	}
	// (Under the mutex, or in the constructor.)
	int Add(const std::string& kindName, int kindDimension, SolverClass kindClass)
	{
		const int id = count.load(std::memory_order_relaxed);
		name[id] = kindName;
		dimension[id] = kindDimension;
		solverClass[id] = kindClass;
		count.store(id + 1, std::memory_order_release);
		return id;
	}
	int Find(const std::string& kindName) const
	{
		const int n = count.load(std::memory_order_acquire);
		for (int i = 0; i < n; ++i)
			if (name[i] == kindName)
				return i;
		return -1;
	}
	bool Registered(ShapeKind kind) const { return kind.Valid() && kind.Id() < count.load(std::memory_order_acquire); }
};

Registry& TheRegistry()
{
	static Registry registry;
	return registry;
}

bool ValidName(const std::string& name)
{
	if (name.empty() || name.size() > 32)
		return false;
	for (char c : name)
		if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'))
			return false;
	return true;
}
} // namespace

const char* SolverClassName(SolverClass solverClass)
{
	switch (solverClass)
	{
	case SolverClass::smoothConvex: return "smooth_convex";
	case SolverClass::convex: return "convex";
	case SolverClass::nonConvex: return "non_convex";
	default: return "none";
	}
}

ShapeKind RegisterShapeKind(const std::string& name, int dimension, SolverClass solverClass)
{
	const char* what = "RegisterShapeKind";
	if (!ValidName(name))
		throw InvalidParameter(std::string(what) + ": field 'name' must be 1 to 32 lower-case letters, digits or '_', got \"" +
		                           name + "\"",
		                       "name");
	if (dimension != 2 && dimension != 3)
		throw InvalidParameter(what, "dimension", "must be 2 or 3", dimension);
	if (solverClass != SolverClass::smoothConvex && solverClass != SolverClass::convex && solverClass != SolverClass::nonConvex)
		throw InvalidParameter(what, "solverClass", "must be smoothConvex, convex or nonConvex", double(int(solverClass)));
	Registry& registry = TheRegistry();
	std::lock_guard<std::mutex> lock(registry.mutex);
	if (registry.Find(name) >= 0)
		throw InvalidParameter(std::string(what) + ": field 'name' must be a new kind's, got \"" + name +
		                           "\", which is registered already",
		                       "name");
	if (registry.count.load(std::memory_order_relaxed) >= ShapeKind::kMaxKinds)
		throw InvalidParameter(std::string(what) + ": field 'name' (\"" + name + "\") cannot be registered: the registry holds " +
		                           std::to_string(ShapeKind::kMaxKinds) + " kinds, its most",
		                       "name");
	return ShapeKind(registry.Add(name, dimension, solverClass));
}

ShapeKind FindShapeKind(const std::string& name)
{
	return ShapeKind(TheRegistry().Find(name));
}

const char* KindName(ShapeKind kind)
{
	const Registry& registry = TheRegistry();
	return registry.Registered(kind) ? registry.name[kind.Id()].c_str() : "none";
}

int KindDimension(ShapeKind kind)
{
	const Registry& registry = TheRegistry();
	return registry.Registered(kind) ? registry.dimension[kind.Id()] : 0;
}

SolverClass KindSolverClass(ShapeKind kind)
{
	const Registry& registry = TheRegistry();
	if (!registry.Registered(kind))
		throw InvalidParameter("KindSolverClass", "kind", "must be a registered kind", kind.Id());
	return registry.solverClass[kind.Id()];
}

int ShapeKindCount()
{
	return TheRegistry().count.load(std::memory_order_acquire);
}

} // namespace b2a
