// b2analytic: the search for the first contact in time, shared by the 2D and 3D time of impact
// (internal).
#pragma once

#include "b2analytic/TimeOfImpact.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>

namespace b2a
{

/// No touch within [0, tMax]: `out` (TimeOfImpactResult or its 3D twin) reports the contact at
/// the end.
template <class Result, class Contact>
Result& ReportNoContact(Result& out, const Contact& end, double tMax)
{
	out.status = SolveStatus::converged;
	out.iterations = std::max(out.iterations, 1);
	out.hit = false;
	out.time = tMax;
	out.contact = end;
	return out;
}

/// The first contact from t0 on, within [t0, tEnd] (tEnd ≤ tMax: past it the particles cannot
/// touch), into `out`: conservative advancement, each step the distance's lower bound
/// `lowerBound(t, contact)` over the approach speed's upper bound `rate`, so that no step passes
/// a contact; a lower bound below 1e-12 of `size` is contact (grazing); below 1e-3 of it the
/// separation's rate of change from a difference, and where a sign change is found ahead,
/// Brent's method on the separation to options.timeTolerance relative. `contactAt(t)` is the
/// contact at time t (separation ≤ 0 exactly when touching). Without a contact by tEnd, the
/// contact at tMax is reported (ReportNoContact).
template <class Result, class ContactAt, class LowerBound>
Result& SearchFirstContact(Result& out, ContactAt&& contactAt, LowerBound&& lowerBound, double t0, double tEnd, double tMax,
                           double rate, double size, const TimeOfImpactOptions& options)
{
	const double switchGap = 1e-3 * size; // below this, look for a sign change to bracket
	const double touchGap = 1e-12 * size; // a lower bound this small is contact (grazing)
	auto hit = [&](double time, const auto& contact) -> Result& {
		out.status = SolveStatus::converged;
		out.hit = true;
		out.time = time;
		out.contact = contact;
		return out;
	};
	double t = t0;
	auto c = contactAt(t);
	for (int it = 0; it < options.maxIterations; ++it)
	{
		out.iterations = it + 1;
		if (!c.Ok())
		{
			out.failure = c.failure;
			return out;
		}
		if (c.touching)
			return hit(t, c);
		const double lb = lowerBound(t, c);
		if (!(rate > 0.0))
			break; // nothing moves relative to the other
		if (lb <= touchGap)
			return hit(t, c);
		if (lb <= switchGap)
		{
			// Close: estimate when the separation reaches zero from its rate of change, and if a
			// sign change is found there, finish with Brent's method on the separation.
			// The difference step is scaled by the time reached, not by tMax: a far horizon
			// (the fuzzer's tMax of 1e291) must not throw the probe out to absurd poses.
			const double dt = std::max(c.separation / rate, 1e-9 * std::max(t, lb / rate));
			const double slope = (contactAt(std::min(tMax, t + dt)).separation - c.separation) / dt;
			if (slope < 0.0)
			{
				const double guess = t + c.separation / -slope;
				const double hi = std::min(tMax, t + 1.5 * (guess - t) + lb / rate);
				const auto chi = contactAt(hi);
				if (chi.Ok() && chi.touching)
				{
					// Touching contacts have separation ≤ 0 and apart ones > 0.
					auto sep = [&](double s) { return contactAt(s).separation; };
					const ScalarResult root = FindRootBrent(sep, t, hi, c.separation, chi.separation,
					                                        options.timeTolerance * std::max(hi, 1e-300), 200);
					out.iterations += root.iterations;
					// The root's bracket ends on the touching side, so the contact reported touches.
					double tr = root.x;
					auto cr = contactAt(tr);
					if (!cr.touching)
					{
						tr = std::min(hi, tr + options.timeTolerance * std::max(hi, 1e-300));
						cr = contactAt(tr);
					}
					return hit(tr, cr);
				}
			}
		}
		const double next = t + lb / rate;
		if (next > tEnd)
			break;
		t = next;
		c = contactAt(t);
	}
	if (out.iterations >= options.maxIterations)
	{
		out.failure = "conservative advancement reached its step cap (TimeOfImpactOptions::maxIterations)";
		return out;
	}
	return ReportNoContact(out, contactAt(tMax), tMax);
}

} // namespace b2a
