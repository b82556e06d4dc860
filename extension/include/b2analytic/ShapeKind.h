// b2analytic: shape kinds, registered at run time, and the solver classes they default to.
#pragma once

#include <cstdint>
#include <string>

namespace b2a
{

/// What a kind's pairs are solved by where no function was registered for them (the dispatch
/// table's default cells): two smooth convex kinds by the Newton chain on the common level, any
/// pair with a merely convex or a non-convex kind by the grid method.
enum class SolverClass : std::uint8_t
{
	smoothConvex, ///< level sets strictly convex, the level twice differentiable (Newton applies)
	convex,       ///< level sets convex, with corners or flat sides (the grid method)
	nonConvex     ///< anything else star-shaped about the centre (the grid method, one-sided)
};

/// "smooth_convex", "convex" or "non_convex".
const char* SolverClassName(SolverClass solverClass);

/// A registered shape kind: what a shape is, as far as choosing a solver for its pairs goes. Its
/// id is small and dense (the dispatch tables are indexed by it). A default-made kind is no
/// kind (Valid() is false); every other comes from RegisterShapeKind, FindShapeKind or
/// BuiltinKinds.
class ShapeKind
{
public:
	/// The most kinds one process can register (built-in ones included).
	static constexpr int kMaxKinds = 64;

	/// No kind.
	constexpr ShapeKind() = default;
	/// The dense id, 0 … kMaxKinds − 1 (−1 for no kind).
	constexpr int Id() const { return m_id; }
	/// Whether this is a kind (registered), not the default-made none.
	constexpr bool Valid() const { return m_id >= 0; }
	/// Same kind.
	friend constexpr bool operator==(ShapeKind a, ShapeKind b) { return a.m_id == b.m_id; }
	/// Different kinds.
	friend constexpr bool operator!=(ShapeKind a, ShapeKind b) { return a.m_id != b.m_id; }

private:
	constexpr explicit ShapeKind(int id) : m_id(std::int16_t(id)) {}
	friend struct BuiltinKinds;
	friend struct BuiltinKinds3; // the 3D ones (b2analytic/3d/ShapeKind3.h)
	friend ShapeKind RegisterShapeKind(const std::string& name, int dimension, SolverClass solverClass);
	friend ShapeKind FindShapeKind(const std::string& name);

	std::int16_t m_id = -1;
};

/// The kinds the library registers itself, before any other (whichever registry function runs
/// first registers them, thread-safely), with these fixed ids. 2D:
///  - circle, ellipse: SuperellipseShape with n = m = 2 (a = b for the circle), in either form;
///  - superellipse: SuperellipseShape with n, m ≥ 2 (not both 2) and the raw level f;
///  - smoothConvex: other smooth, strictly convex shapes (the ζ-form with ζ > 1, user shapes
///    declared smooth);
///  - convex: convex shapes with corners or flat sides (exponents below 2, user shapes declared
///    convex but not smooth);
///  - nonConvex: the heart, user shapes not declared convex.
struct BuiltinKinds
{
	static constexpr ShapeKind circle{0};       ///< "circle", smoothConvex
	static constexpr ShapeKind ellipse{1};      ///< "ellipse", smoothConvex
	static constexpr ShapeKind superellipse{2}; ///< "superellipse", smoothConvex
	static constexpr ShapeKind smoothConvex{3}; ///< "smooth_convex", smoothConvex
	static constexpr ShapeKind convex{4};       ///< "convex", convex
	static constexpr ShapeKind nonConvex{5};    ///< "non_convex", nonConvex
	/// How many there are (ids 0 … count − 1).
	static constexpr int count = 6;
	/// Their names, by id.
	static constexpr const char* names[count] = {"circle", "ellipse", "superellipse", "smooth_convex", "convex", "non_convex"};
	/// Their solver classes, by id.
	static constexpr SolverClass solverClasses[count] = {SolverClass::smoothConvex, SolverClass::smoothConvex,
	                                                     SolverClass::smoothConvex, SolverClass::smoothConvex,
	                                                     SolverClass::convex,       SolverClass::nonConvex};
	/// The kinds, by id.
	static constexpr ShapeKind all[count] = {circle, ellipse, superellipse, smoothConvex, convex, nonConvex};
};

/// Register a new kind: `name` unique, of lower-case letters, digits and '_' (1 to 32 of them);
/// `dimension` 2 or 3 (a kind's shapes and table are of one dimension); `solverClass` what its
/// pairs default to. Thread-safe; the id is the next free one. Throws InvalidParameter naming
/// the field and the value for a bad or taken name, a dimension other than 2 or 3, a solver
/// class out of range, or a registry already holding ShapeKind::kMaxKinds kinds.
ShapeKind RegisterShapeKind(const std::string& name, int dimension, SolverClass solverClass);

/// The kind registered under `name`, or no kind (Valid() false) where there is none.
ShapeKind FindShapeKind(const std::string& name);

/// The kind's name ("circle", "ellipse", ...), or "none" for no kind or an id never registered.
const char* KindName(ShapeKind kind);

/// The kind's dimension (2 or 3); 0 for no kind.
int KindDimension(ShapeKind kind);

/// The kind's solver class. Throws InvalidParameter (field 'kind') for no kind.
SolverClass KindSolverClass(ShapeKind kind);

/// The number of kinds registered so far (built-in ones included): ids 0 … count − 1.
int ShapeKindCount();

} // namespace b2a
