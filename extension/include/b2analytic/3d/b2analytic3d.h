// b2analytic: the 3D geometry core in one include (superellipsoids, their contact and time of
// impact; no Box2D: Box2D is 2D).
#pragma once

#include "b2analytic/3d/Contact3.h"
#include "b2analytic/3d/ContactResult3.h"
#include "b2analytic/3d/Math3.h"
#include "b2analytic/3d/Shape3.h"
#include "b2analytic/3d/ShapeKind3.h"
#include "b2analytic/3d/SuperellipsoidShape.h"
#include "b2analytic/3d/TimeOfImpact3.h"
