// b2analytic: the dispatch table over pairs of shape kinds, for any dimension (internal).
#pragma once

#include "b2analytic/Shape.h"
#include "b2analytic/ShapeKind.h"

#include <string>

/// Requires constant initialization of a variable (C++20's constinit, as the compilers offer it
/// in C++17): a dispatch table filled at compile time.
#if defined(__clang__)
#define B2A_CONSTINIT [[clang::require_constant_initialization]]
#elif defined(__GNUC__)
#define B2A_CONSTINIT __constinit
#else
#define B2A_CONSTINIT
#endif

namespace b2a
{

/// A function of a PairTable's cell, and whether it was registered for the pair the other way
/// round (flipped): it is then called with A and B swapped and its answer flipped back. A null
/// function is none registered: the table's default by the kinds' solver classes answers.
template <typename Function>
struct PairEntry
{
	Function function = nullptr; ///< the function, or null
	bool flipped = false;        ///< registered for (B, A)
};

/// A cell's two functions: the contact function and the common-level function of a pair of
/// kinds (A's, B's).
template <typename ContactFn, typename LevelFn>
struct PairCell
{
	ContactFn contact = nullptr; ///< the contact function
	LevelFn level = nullptr;     ///< the common-level function
};

/// The one table that decides which solver handles a pair of shape kinds of one dimension: the 2D
/// table (functions of Shape, Pose, ContactResult) and the 3D one are instantiations of this.
/// Indexed by the kinds' ids, ShapeKind::kMaxKinds squared, so that a kind registered later needs
/// no resizing: its cells stay null, and the default by solver classes (`byClass`) answers for
/// them until a function is registered. Everything here is constexpr, so that a table whose
/// built-in cells are filled by a constexpr constructor is constant-initialized (no guard on
/// the lookup, no order of initialisation to get wrong). Reads take no lock; writes (Set*) are
/// for set-up, before the pairs they change are solved (not synchronised with running solves).
template <typename ContactFn, typename LevelFn>
class PairTable
{
public:
	/// Both functions of a cell.
	using Cell = PairCell<ContactFn, LevelFn>;
	/// The cell of a pair of solver classes.
	using ClassCell = Cell (*)(SolverClass a, SolverClass b);

	/// An empty table of kinds of `dimension`, with its defaults by solver classes.
	constexpr PairTable(int dimension, ClassCell byClass) : m_dimension(dimension), m_byClass(byClass) {}

	/// The contact function for (a, b), and whether it is stored flipped.
	ContactFn Contact(ShapeKind a, ShapeKind b, bool& flipped) const
	{
		const PairEntry<ContactFn>& e = m_contact[a.Id()][b.Id()];
		flipped = e.flipped;
		return e.function ? e.function : DefaultCell(a, b).contact;
	}
	/// The common-level function for (a, b), and whether it is stored flipped.
	LevelFn Level(ShapeKind a, ShapeKind b, bool& flipped) const
	{
		const PairEntry<LevelFn>& e = m_level[a.Id()][b.Id()];
		flipped = e.flipped;
		return e.function ? e.function : DefaultCell(a, b).level;
	}

	/// Set the contact function of (a, b) in that order; (b, a) gets it flipped. A function that
	/// takes its pair in either order is set with `symmetric` (no flip either way).
	constexpr void SetContact(ShapeKind a, ShapeKind b, ContactFn f, bool symmetric = false) { Set(m_contact, a, b, f, symmetric); }
	/// The same for the common-level function.
	constexpr void SetLevel(ShapeKind a, ShapeKind b, LevelFn f, bool symmetric = false) { Set(m_level, a, b, f, symmetric); }
	/// Both functions of (a, b), each taking its pair in either order.
	constexpr void SetCell(ShapeKind a, ShapeKind b, const Cell& cell)
	{
		SetContact(a, b, cell.contact, true);
		SetLevel(a, b, cell.level, true);
	}

	/// Throws InvalidParameter unless `kind` is a registered kind of this table's dimension
	/// (`who`: the public function's name, `field`: the argument's).
	void RequireKind(ShapeKind kind, const char* who, const char* field) const
	{
		if (KindDimension(kind) == 0)
			throw InvalidParameter(who, field, "must be a registered shape kind (id)", kind.Id());
		if (KindDimension(kind) != m_dimension)
			throw InvalidParameter(std::string(who) + ": field '" + field + "' must be a kind of dimension " +
			                           std::to_string(m_dimension) + ", got \"" + KindName(kind) + "\" of dimension " +
			                           std::to_string(KindDimension(kind)),
			                       field);
	}

private:
	static constexpr int K = ShapeKind::kMaxKinds;

	Cell DefaultCell(ShapeKind a, ShapeKind b) const { return m_byClass(KindSolverClass(a), KindSolverClass(b)); }

	template <typename F>
	static constexpr void Set(PairEntry<F> (&entries)[K][K], ShapeKind a, ShapeKind b, F f, bool symmetric)
	{
		entries[a.Id()][b.Id()] = PairEntry<F>{f, false};
		if (a != b)
			entries[b.Id()][a.Id()] = PairEntry<F>{f, !symmetric};
	}

	int m_dimension;
	ClassCell m_byClass;
	PairEntry<ContactFn> m_contact[K][K] = {};
	PairEntry<LevelFn> m_level[K][K] = {};
};

/// A column of the table for a kind of geometry that has no shape kind (the 2D table's polygons
/// and segments, Box2D's plain shapes): one function per shape kind, the same default for every
/// kind until one is registered for it. constexpr, lock-free reads and set-up writes, as
/// PairTable.
template <typename Function>
class KindColumn
{
public:
	/// A column whose every kind has `byDefault`.
	constexpr explicit KindColumn(Function byDefault) : m_default(byDefault) {}
	/// The function for `kind`.
	Function At(ShapeKind kind) const
	{
		const Function f = m_entries[kind.Id()];
		return f ? f : m_default;
	}
	/// Register `f` for `kind`.
	constexpr void Set(ShapeKind kind, Function f) { m_entries[kind.Id()] = f; }

private:
	Function m_default;
	Function m_entries[ShapeKind::kMaxKinds] = {};
};

} // namespace b2a
