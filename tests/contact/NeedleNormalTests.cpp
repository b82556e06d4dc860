// Contact normals beside needle-shaped superellipses, from the stress benchmark
// (demos/benchmarks/b2a_stress.cpp, seed 1, configurations named by index; poses and shapes in
// hex floats as it wrote them), and perturbed neighbours of each.
//
// References, in long double (ContactReference.h; the library is used only for the poses'
// cosine and sine): the optimality conditions solved by Newton (PolishLagrange) from the
// library's point, and held to be solved (levels to 1e-12, normals opposed to 1e-12 rad) before
// they are used, so that a reference that did not converge fails the test rather than passes it;
// at a heart's tip, where there are no conditions, the tip's one-sided scale (PolishTip of
// StressReference.h).
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "ContactReference.h"
#include "StressReference.h"

#include <cmath>
#include <string>
#include <vector>

using namespace b2a;
namespace ref = b2a::test::ref;
using ref::LD;
using ref::V;

namespace
{
/// A shape as the stress run wrote it.
struct Spec
{
	bool heart = false;
	double a = 0.0, b = 0.0, n = 0.0, m = 0.0; // (a: the heart's α)
	static Spec Heart(double alpha) { return {true, alpha, 0.0, 0.0, 0.0}; }
	static Spec Super(double a, double b, double n, double m) { return {false, a, b, n, m}; }
	ShapePtr Make() const { return heart ? ShapePtr(MakeHeart(a)) : ShapePtr(MakeSuperellipse(a, b, n, m)); }
	ref::RefShape Ref() const { return heart ? ref::RefShape::Heart(a) : ref::RefShape::Super(a, b, n, m); }
};

/// A configuration of the stress run.
struct Config
{
	int index;
	Spec a, b;
	Pose pa, pb;
};

/// The configuration and its neighbours: B moved by 1e-9 and 1e-7 of the smaller particle's
/// bounding radius along each axis, and A turned by ±`turn` rad (1e-7 unless given).
std::vector<std::pair<Pose, Pose>> Neighbours(const Config& c, double size, double turn = 1e-7)
{
	std::vector<std::pair<Pose, Pose>> poses{{c.pa, c.pb}};
	for (double d : {1e-9, -1e-7})
	{
		poses.push_back({c.pa, Pose(c.pb.p + Vec2(d * size, 0.0), c.pb.q)});
		poses.push_back({c.pa, Pose(c.pb.p + Vec2(0.0, d * size), c.pb.q)});
	}
	for (double t : {turn, -turn})
		poses.push_back({Pose(c.pa.p, std::atan2(c.pa.q.s, c.pa.q.c) + t), c.pb});
	return poses;
}

/// The angle between two unit directions (long double).
LD Angle(V u, V v) { return std::atan2(std::fabs(ref::Cross(u, v)), ref::Dot(u, v)); }

/// Whether X solves the conditions in long double: A's and B's unit normals opposed to 1e-12
/// rad, and `level` of B (the one-sided scale, common false) or of both (common true) within
/// 1e-12 of each other.
bool Solved(const ref::RefShape& A, const ref::RefPose& pa, const ref::RefShape& B, const ref::RefPose& pb, V X, bool common,
            LD level)
{
	const ref::Deriv da = ref::WorldDeriv(A, pa, X), db = ref::WorldDeriv(B, pb, X);
	const LD lb = B.Level(ref::ToBodyL(pb, X)), la = A.Level(ref::ToBodyL(pa, X));
	const bool levels = common ? std::fabs(la - lb) <= 1e-12L * la : std::fabs(lb - level) <= 1e-12L * level;
	return levels && Angle(ref::Unit(da.grad), -1.0L * ref::Unit(db.grad)) <= 1e-12L;
}

// Hearts beside needles, in range (size ratio below 1e4): the one-sided grid scale's point is
// right to ~1e-12 of the size, and the needle's normal there turns by 1e4 or more times the
// heart's with the point's error. The contact's normal, the mean of the two, carried half the
// needle's turn: 1.1e-6 to 3.8e-4 rad.
const std::vector<Config> kHeartNeedles = {
	{399724, Spec::Heart(0x1.e5e2834ec30f9p+8), Spec::Super(0x1.814a5b0b85c15p-17, 0x1.4a46df31ae0c9p-8, 0x1.09d82377a8309p+3, 0x1.4e6ac26034d66p+3), Pose(Vec2(-0x1.1caefc3d2a126p+8, -0x1.c9d4c7172d2a4p+6), -0x1.81b53dce47c36p+1), Pose(Vec2(-0x1.b8e73cee8da93p-7, -0x1.9e9d972c68bc1p-8), 0x1.f223ec179781p+0)},
	{550116, Spec::Heart(0x1.32d3ca4ab76bfp+6), Spec::Super(0x1.a53b780151b7ep-19, 0x1.17527c590a23ep-9, 0x1p+1, 0x1p+1), Pose(Vec2(0x1.3e2809a10f79bp+6, 0x1.f19e36f4e20b7p+2), -0x1.022c120423f5ap+1), Pose(Vec2(-0x1.2319254a62778p-7, 0x1.c4ea6f8859ad6p-8), 0x1.08701b76b3d72p+1)},
	{589624, Spec::Super(0x1.52ecba7c403f3p-16, 0x1.049d9c9054583p-6, 0x1.8p+3, 0x1.8p+3), Spec::Heart(0x1.d368820655c77p+13), Pose(Vec2(0x1.7235933898dc1p-5, 0x1.5d7d0b4feac1dp-9), -0x1.35e1fece6659p-2), Pose(Vec2(0x1.89e30609a7378p+5, 0x1.b7b49b7597505p+6), 0x1.fc0ccfc5c6f98p-1)},
	{643116, Spec::Heart(0x1.ad5c2565cb08dp+9), Spec::Super(0x1.1ac26258f0a07p-16, 0x1.49987fb195b5bp-7, 0x1.e76a8ca11d57p+3, 0x1.328d28a0334a8p+3), Pose(Vec2(0x1.79dc7251dbe29p+3, 0x1.76a2d7b8b091ap+5), -0x1.fa1f37d9f8e0ap+0), Pose(Vec2(-0x1.0ba497d5f683cp-6, -0x1.0a1498f8d93f9p-5), 0x1.44fdb96ea49e8p+1)},
	{758143, Spec::Super(0x1.16ec553b43559p-4, 0x1.768b0b8d4d58cp-14, 0x1p+1, 0x1p+1), Spec::Heart(0x1.1b1d0cafe3365p+7), Pose(Vec2(-0x1.e549d67422137p-3, -0x1.125b7f8b599a7p-2), 0x1.7207ca5ab63a4p+0), Pose(Vec2(0x1.f5a1a85b836f7p+0, 0x1.4fc8d2865ae5ep+3), -0x1.591214b7acaa4p+0)},
	{803951, Spec::Super(0x1.d9570a9742dafp-7, 0x1.e4b33e0b880b3p-17, 0x1p+1, 0x1p+1), Spec::Heart(0x1.b00868298ebaap-12), Pose(Vec2(0x1.9db965e15fc31p-5, -0x1.2652f9bdae3afp-2), 0x1.d6de1b182d994p+0), Pose(Vec2(-0x1.aa5320d708623p-5, 0x1.674af1e7e8ea5p-3), -0x1.25cc9fcfb0882p+1)},
	{918989, Spec::Heart(0x1.34b9dade1f645p+7), Spec::Super(0x1.e973a94059a82p-7, 0x1.18a9d29ddf64bp-14, 0x1.8p+2, 0x1.8p+2), Pose(Vec2(-0x1.efc0c0b222fe2p+5, 0x1.2e462f5c516a7p+8), -0x1.0f8da2f2965e4p-1), Pose(Vec2(0x1.a1350e108ecccp-5, 0x1.4ad50fdcf471ap-8), -0x1.3b89d63387c8p-1)},
	{930551, Spec::Super(0x1.73586298d25cp-15, 0x1.bbfff85ee2a25p-9, 0x1p+1, 0x1p+1), Spec::Heart(0x1.749c0f8fd030ep+9), Pose(Vec2(0x1.6a4f83f82b6d9p-8, 0x1.91757f1e75409p-7), -0x1.ffefc2e03018p-3), Pose(Vec2(0x1.7a865f90b01c9p+0, -0x1.d6fedf23ab4b5p+4), -0x1.048f81ee03b6ep+0)},
};

// Needles crossing deep inside each other (common levels of 1e-20 to 1e-18): Newton's levels
// agreed to 1e-11 in double while the rounding of its point alone turned the normals by 1e3 rad
// and more, and the true normals there were 0.04 to 2.4 rad apart.
const std::vector<Config> kDeepNeedles = {
	{264505, Spec::Super(0x1.c6278dc905c3dp-6, 0x1.aa9868a583074p-10, 0x1.ep+3, 0x1p+1), Spec::Super(0x1.cf924b21481aep-4, 0x1.919d98ccdd1b4p-12, 0x1.ep+3, 0x1.6p+3), Pose(Vec2(0x1.7f9cfe4ace47p-4, -0x1.e0204c2bc4203p-5), -0x1.dca03a393f961p+0), Pose(Vec2(0x1.7b6f8fe7a9e94p-4, -0x1.cbd4f515d5a14p-5), -0x1.e1c74459672d8p-2)},
	{298732, Spec::Super(0x1.026e3cee8f67ep-8, 0x1.2e589b0c33e0bp-17, 0x1.4p+4, 0x1p+1), Spec::Super(0x1.797c983f22a9fp-15, 0x1.81208028e255ap-6, 0x1.2p+4, 0x1.2p+4), Pose(Vec2(-0x1.1ab134deffec6p-8, 0x1.1c610608c665bp-8), 0x1.f393393aed58cp+0), Pose(Vec2(-0x1.36ab245d618d6p-8, 0x1.e3083dc9fee61p-9), 0x1.e13452515eb3p+0)},
	{479467, Spec::Super(0x1.3b0f3143dbddbp-1, 0x1.dc96bd95d0238p+6, 0x1p+1, 0x1.1p+4), Spec::Super(0x1.18ab2202740cfp+1, 0x1.f38d89ce785cdp+7, 0x1.9f4e17d1da8dep+3, 0x1.75e706b6762b1p+3), Pose(Vec2(0x1.4c141026add2fp+7, -0x1.04f7f473914fbp+7), 0x1.811bca0dd5f7p+1), Pose(Vec2(0x1.4750777e5edd9p+7, -0x1.eded5777add2ap+6), 0x1.072e05e2e7816p+1)},
};

// A needle (0.0007 × 0.22, n = 15, m = 3.75) 600 sizes from a 5.5 × 640 plank: their common level
// is 3.7e24, where A's level set is a needle of aspect 2.6e7 reaching 7.7e5 from its centre.
// Newton and the min–max stop short, and the grid sampling B's level-C surface (aspect 1.8e5)
// straddled the minimum of λA over it (level 1.2e26 for 3.7e24); A's samples find it.
const Config kFarNeedle = {583459, Spec::Super(0x1.6ec24bbf4c26fp-11, 0x1.c53b6dc885962p-3, 0x1.e17fe3a170563p+3, 0x1.e0a127080d28bp+1),
                           Spec::Super(0x1.62e26fab25221p+2, 0x1.405a867d1c9a6p+9, 0x1.e78ebe17cfa35p+3, 0x1.46a568c97f753p+2),
                           Pose(Vec2(-0x1.0e7403cdb0ccfp-2, 0x1.38796719f17ebp-4), 0x1.a16e9acf8ffc8p-1),
                           Pose(Vec2(0x1.849fcdd6d7a32p+6, -0x1.357f9497849eep+9), 0x1.a1540585059ccp-1)};

// A heart's tip against a needle's end (curvature 1e8 to 1e9 of the heart's size): the normal is
// the needle's at the tip, which turned by 1.1e-6 to 1.7e-6 rad with the tip's place rounded in
// world coordinates (the centres 10 to 1e5 of the needle's size apart). And a heart 1.6e-10 below
// its own level at the tip of an 85:1 plank (23851), whose tip is not its own-level corner; and a
// heart at its own level at a 1000:1 needle's end scaled 2.3e-11 below its own (811943), where the
// heart's level at the rounded point, 1e-10 off across its tip's kink, looked the farther one.
const std::vector<Config> kHeartTips = {
	{93551, Spec::Heart(0x1.9799c428d09dep+4), Spec::Super(0x1.2d680f5ea3365p-8, 0x1.aebb0c028aed6p-18, 0x1p+1, 0x1p+1), Pose(Vec2(-0x1.379e6fe27852ep+7, 0x1.1573a4fc4fdfp+5), 0x1.5a101b032a534p+0), Pose(Vec2(-0x1.1c64e2a1a824cp-7, 0x1.3918c046306aap-8), -0x1.5eb07e263f3a8p-1)},
	{96670, Spec::Super(0x1.12df1ed80f1ep-20, 0x1.0624dd2f1a9fcp-10, 0x1p+1, 0x1p+1), Spec::Heart(0x1.d5ed73171d33fp+3), Pose(Vec2(-0x1.731d63c1720bfp-10, -0x1.744972738d272p-11), -0x1.70b18aea405b4p+0), Pose(Vec2(0x1.ab622de831b4dp-2, 0x1.e77d2fa1d3319p+1), -0x1.c058ffd27c92p-4)},
	{492370, Spec::Super(0x1.6723c2b870a7bp-1, 0x1.6fc2509c193f3p-11, 0x1p+1, 0x1p+1), Spec::Heart(0x1.2783ae3279f81p+19), Pose(Vec2(0x1.0cf9f030cc77cp-2, 0x1.82ed889cb755bp+0), -0x1.4bda27b48fb5p-2), Pose(Vec2(0x1.ecb781c681fdep+5, 0x1.84875593e3ed9p+9), -0x1.437a654a78ap-4)},
	{587016, Spec::Super(0x1.da75a3718ada9p-17, 0x1.f6cb346d05869p-8, 0x1p+1, 0x1p+1), Spec::Heart(0x1.a4d82bb7a7881p+7), Pose(Vec2(-0x1.1aacc84586d57p-6, -0x1.8aca152d86b2cp-6), -0x1.7f2f5a2ba7822p+0), Pose(Vec2(-0x1.764ae0cfd1d22p+2, 0x1.a8445a68e290fp+3), 0x1.a795e8636dbap-2)},
	{23851, Spec::Heart(0x1.2e5360c5888c7p+4), Spec::Super(0x1.04d24079034c1p-6, 0x1.8751e970e58e5p-13, 0x1.2cd528eda107dp+4, 0x1.5cb83c070cb0fp+3), Pose(Vec2(-0x1.2e65770166161p+1, 0x1.dd449b4306fa1p+1), 0x1.20f3edd4b3d9cp-1), Pose(Vec2(-0x1.354223e392611p-5, 0x1.472126a2e144p-5), 0x1.8b21f581b9998p+0)},
	{811943, Spec::Super(0x1.7bec7ccb4778bp-12, 0x1.7304f1de83cbep-2, 0x1p+1, 0x1p+1), Spec::Heart(0x1.824d14661a68cp-6), Pose(Vec2(0x1.4951d552aac06p-3, 0x1.05e632ed62691p-3), -0x1.547d66457fb4fp+1), Pose(Vec2(0x1.61f8bc5310883p-2, -0x1.6224cde4f1791p-2), -0x1.83dc6027f730fp+1)},
};
} // namespace

TEST_CASE("needle normals: a heart's tip against a needle's end gets the needle's normal to 1e-6 rad")
{
	for (const Config& c : kHeartTips)
	{
		const ShapePtr a = c.a.Make(), b = c.b.Make();
		const ref::RefShape ra = c.a.Ref(), rb = c.b.Ref();
		const double size = std::min(a->BoundingRadius(), b->BoundingRadius());
		const bool heartA = c.a.heart;
		// A turned so that the tip moves by 1e-7 of the needle's size (the heart's centre is
		// 10 to 1e5 of it away).
		for (const auto& [pa, pb] : Neighbours(c, size, 1e-7 * size / Distance(c.pa.p, c.pb.p)))
		{
			CAPTURE(c.index);
			const ContactResult r = ComputeContact(*a, pa, *b, pb);
			REQUIRE(r.Ok());
			const stress::Posed A{ra, ref::Of(pa)}, B{rb, ref::Of(pb)};
			const stress::Posed &heart = heartA ? A : B, &needle = heartA ? B : A;
			// The contact's point is the heart's tip: on its axis, below its centre.
			const V x = ref::ToBodyL(heart.pose, ref::FromVec(r.point));
			REQUIRE(std::fabs(x.x) <= 1e-9L * size);
			REQUIRE(x.y < 0.0L);
			// The heart at its own level there (its tip fixed), or scaled onto the needle's surface:
			// whichever is nearer its own level (the heart's on its axis, x.y², where it is smooth).
			const V X = ref::FromVec(r.point);
			const bool own = std::fabs(x.y * x.y / heart.shape.Own() - 1.0L) <
			                 std::fabs(stress::LevelAt(needle, X) / needle.shape.Own() - 1.0L);
			const stress::LevelSolution tip = own ? stress::PolishTip(needle, heart, false, 1.0L)
			                                      : stress::PolishTip(heart, needle, true, x.y * x.y);
			REQUIRE(tip.ok);
			if (own)
				CHECK(std::fabs(stress::LevelAt(needle, tip.point) / LD(r.level) - 1.0L) <= 1e-9L);
			const V out = ref::Unit(stress::WorldDeriv(needle, tip.point).grad); // the needle's outward normal
			const V n = heartA ? V{-out.x, -out.y} : out;
			CHECK(double(Angle(ref::FromVec(r.normal), n)) <= 1e-6);
		}
	}
}

TEST_CASE("needle normals: a needle far from a plank (common level 3.7e24) gets its level to 1e-9 and normal to 1e-6 rad")
{
	const Config& c = kFarNeedle;
	const ShapePtr a = c.a.Make(), b = c.b.Make();
	const ref::RefShape ra = c.a.Ref(), rb = c.b.Ref();
	const double size = std::min(a->BoundingRadius(), b->BoundingRadius());
	for (const auto& [pa, pb] : Neighbours(c, size))
	{
		const ref::RefPose qa = ref::Of(pa), qb = ref::Of(pb);
		for (bool swapped : {false, true})
		{
			CAPTURE(swapped);
			const LevelResult r = swapped ? SolveCommonLevel(*b, pb, *a, pa) : SolveCommonLevel(*a, pa, *b, pb);
			REQUIRE(r.Ok());
			const V Xr = ref::PolishLagrange(ra, qa, rb, qb, ref::FromVec(r.point), true);
			const LD level = ra.Level(ref::ToBodyL(qa, Xr));
			REQUIRE(Solved(ra, qa, rb, qb, Xr, true, level));
			CHECK(level > 1e24L);
			CHECK(double(std::fabs(LD(r.level) - level) / level) <= 1e-9);
			// A's gradient direction, from the first particle solved.
			const V n = ref::Unit(ref::WorldDeriv(swapped ? rb : ra, swapped ? qb : qa, Xr).grad);
			CHECK(double(Angle(ref::FromVec(r.normal), n)) <= 1e-6);
		}
		const ContactResult contact = ComputeContact(*a, pa, *b, pb);
		REQUIRE(contact.Ok());
		CHECK_FALSE(contact.touching);
	}
}

TEST_CASE("needle normals: a heart beside a needle gets the contact normal to 1e-6 rad")
{
	for (const Config& c : kHeartNeedles)
	{
		const ShapePtr a = c.a.Make(), b = c.b.Make();
		const ref::RefShape ra = c.a.Ref(), rb = c.b.Ref();
		const double size = std::min(a->BoundingRadius(), b->BoundingRadius());
		for (const auto& [pa, pb] : Neighbours(c, size))
		{
			CAPTURE(c.index);
			const ContactResult r = ComputeContact(*a, pa, *b, pb);
			REQUIRE(r.Ok());
			// The grid's point lies on one particle's surface with the other rescaled onto it: the
			// reference solves that side's conditions from the point.
			const ref::RefPose qa = ref::Of(pa), qb = ref::Of(pb);
			const V X = ref::FromVec(r.point);
			const bool onB = std::fabs(rb.Level(ref::ToBodyL(qb, X)) / rb.Own() - 1.0L) <
			                 std::fabs(ra.Level(ref::ToBodyL(qa, X)) / ra.Own() - 1.0L);
			const ref::RefShape& scaled = onB ? ra : rb;
			const ref::RefShape& surface = onB ? rb : ra;
			const ref::RefPose &ps = onB ? qa : qb, &pt = onB ? qb : qa;
			const V Xr = ref::PolishLagrange(scaled, ps, surface, pt, X, false, surface.Own());
			REQUIRE(Solved(scaled, ps, surface, pt, Xr, false, surface.Own()));
			// A's outward normal at the reference point (the contact's, from A to B).
			const V n = ref::Unit(ref::WorldDeriv(ra, qa, Xr).grad);
			CHECK(double(Angle(ref::FromVec(r.normal), n)) <= 1e-6);
		}
	}
}

TEST_CASE("needle normals: needles deep inside each other get no converged level with opposed normals only in double")
{
	// Each solver that reports the common level converged answers a point where the normals are
	// opposed in long double to 1e-6 rad; where no level meets that, the contact separates the
	// pair along the axis of least overlap (ContactFromLevelChain).
	for (const Config& c : kDeepNeedles)
	{
		const ShapePtr a = c.a.Make(), b = c.b.Make();
		const ref::RefShape ra = c.a.Ref(), rb = c.b.Ref();
		const double size = std::min(a->BoundingRadius(), b->BoundingRadius());
		for (const auto& [pa, pb] : Neighbours(c, size))
		{
			CAPTURE(c.index);
			const ref::RefPose qa = ref::Of(pa), qb = ref::Of(pb);
			auto opposed = [&](Vec2 point) {
				const V X = ref::FromVec(point);
				return double(Angle(ref::Unit(ref::WorldDeriv(ra, qa, X).grad), -1.0L * ref::Unit(ref::WorldDeriv(rb, qb, X).grad)));
			};
			const LevelResult level = SolveCommonLevel(*a, pa, *b, pb);
			if (level.Ok())
				CHECK(opposed(level.point) <= 1e-6);
			const ContactResult r = ComputeContact(*a, pa, *b, pb);
			REQUIRE(r.Ok());
			if (r.method == SolveMethod::overlapAxis)
				CHECK(r.touching);
			else
				CHECK(opposed(r.point) <= 1e-6);
		}
	}
}
