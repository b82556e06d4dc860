// b2analytic: the built-in 3D shape kinds (kinds of dimension 3 in the one registry).
#pragma once

#include "b2analytic/ShapeKind.h"

namespace b2a
{

/// The 3D kinds the library registers itself, right after the 2D ones (BuiltinKinds), with
/// these fixed ids:
///  - sphere, ellipsoid: SuperellipsoidShape with every exponent 2 (a = b = c for the sphere);
///  - superellipsoid: SuperellipsoidShape with every exponent ≥ 2 (not all 2): smooth;
///  - convexSuperellipsoid: SuperellipsoidShape with an exponent below 2 (edges or infinite
///    curvature: the grid method's).
struct BuiltinKinds3
{
	static constexpr ShapeKind sphere{BuiltinKinds::count + 0};               ///< "sphere", smoothConvex
	static constexpr ShapeKind ellipsoid{BuiltinKinds::count + 1};            ///< "ellipsoid", smoothConvex
	static constexpr ShapeKind superellipsoid{BuiltinKinds::count + 2};       ///< "superellipsoid", smoothConvex
	static constexpr ShapeKind convexSuperellipsoid{BuiltinKinds::count + 3}; ///< "convex_superellipsoid", convex
	/// How many there are (ids BuiltinKinds::count … BuiltinKinds::count + count − 1).
	static constexpr int count = 4;
	/// Their names, in id order.
	static constexpr const char* names[count] = {"sphere", "ellipsoid", "superellipsoid", "convex_superellipsoid"};
	/// Their solver classes, in id order.
	static constexpr SolverClass solverClasses[count] = {SolverClass::smoothConvex, SolverClass::smoothConvex,
	                                                     SolverClass::smoothConvex, SolverClass::convex};
	/// The kinds, in id order.
	static constexpr ShapeKind all[count] = {sphere, ellipsoid, superellipsoid, convexSuperellipsoid};
};

} // namespace b2a
