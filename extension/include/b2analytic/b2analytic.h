// b2analytic: analytic-shape particles for Box2D 2.4. Include this for everything.
#pragma once

#include "b2analytic/Math.h"
#include "b2analytic/ShapeKind.h"
#include "b2analytic/Shape.h"
#include "b2analytic/SuperellipseShape.h"
#include "b2analytic/HeartShape.h"
#include "b2analytic/UserShape.h"
#include "b2analytic/ContactResult.h"
#include "b2analytic/CommonLevel.h"
#include "b2analytic/Contact.h"
#include "b2analytic/TimeOfImpact.h"
#include "b2analytic/SurfaceQueries.h"
#include "b2analytic/PolygonContact.h"
#include "b2analytic/ContactManifold.h"
