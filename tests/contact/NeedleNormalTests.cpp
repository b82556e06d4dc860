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

// Needles crossing deep inside each other: the 25 in-range failures of the seed-1 run before
// the level chain solved in a particle's own frame (common levels 1.8e-30 to 9.2e-10; 264505,
// 298732 and 479467 among them, where Newton's levels had agreed to 1e-11 in double while the
// rounding of its point turned the normals by 1e3 rad). With an exponent 2 across a needle its
// level set is 1e-15 of its size thick there, below what world coordinates hold.
const std::vector<Config> kDeepNeedles = {
	{10159, Spec::Super(0x1.68f5c8f86c328p-1, 0x1.6080064299a95p+9, 0x1p+1, 0x1.2p+4), Spec::Super(0x1.12a375acc877fp+9, 0x1.363fdea127f9p-1, 0x1.4p+4, 0x1.4p+4), Pose(Vec2(0x1.8e901e4f1d829p+9, -0x1.561713552e461p+8), -0x1.f517ca63d0348p-1), Pose(Vec2(0x1.8e92bbc6c4865p+9, -0x1.6507cc254ac2cp+8), 0x1.599bffb4bbb5cp+1)},
	{26759, Spec::Super(0x1.0f223c7abe6a6p-3, 0x1.330b6314454d6p-13, 0x1.4p+4, 0x1.4p+4), Spec::Super(0x1.8d0f4e5a48ea2p-12, 0x1.be4b3a062cc21p-5, 0x1.48192e73f25ap+1, 0x1.d6bf964ebb708p+3), Pose(Vec2(-0x1.71496f561f1b9p-3, -0x1.dc3ca32dce29fp-9), -0x1.4503df09215f9p+1), Pose(Vec2(-0x1.62956d9af85aap-3, 0x1.cab1573c1816ap-10), -0x1.dd080dd5d3bf8p-2)},
	{137705, Spec::Super(0x1.8ce50385526ddp-7, 0x1.a8c8232898977p+2, 0x1.8p+1, 0x1.2p+4), Spec::Super(0x1.ea70beebc9bc2p+0, 0x1.3724d9b19968ep-9, 0x1.ep+3, 0x1.2p+4), Pose(Vec2(-0x1.def85d4b1c776p-1, -0x1.536c81312dfa4p+2), -0x1.96fa05beaa84cp+0), Pose(Vec2(-0x1.059e309d3475p+0, -0x1.520551e433ee3p+2), -0x1.392fabb556188p-2)},
	{176613, Spec::Super(0x1.104de876f608cp-3, 0x1.10499142dbc3cp-9, 0x1.4p+4, 0x1.4p+4), Spec::Super(0x1.a24eb3cc72ff2p-1, 0x1.1f986602a2465p-10, 0x1.4p+3, 0x1p+1), Pose(Vec2(-0x1.945f1e5ae4485p-3, -0x1.78822f17c931dp-3), 0x1.351ec0e8d9ddp+0), Pose(Vec2(-0x1.e9cade8855e6fp-4, -0x1.15847a75f189ep-3), 0x1.f3e68ec8270ep-3)},
	{184099, Spec::Super(0x1.2b79c9debd03p-12, 0x1.2474ef238494fp-2, 0x1.03ab9c70239e4p+1, 0x1.e101dc9bb5765p+3), Spec::Super(0x1.eb5e18ca77515p-3, 0x1.f7290f25575d8p-13, 0x1.4p+4, 0x1.4p+4), Pose(Vec2(0x1.7a30f9e3d1614p-1, 0x1.d0e5721b48613p-2), 0x1.662dd05ef03d8p-1), Pose(Vec2(0x1.375329207793cp-1, 0x1.0151de736371cp-1), 0x1.2cb1bd33625ap-4)},
	{220899, Spec::Super(0x1.1a1303bb7dd3bp-8, 0x1.137691a518e0cp+2, 0x1.e3d88c5a0b6fdp+3, 0x1.0e7f041f8783ap+4), Spec::Super(0x1.be73499484ed6p-10, 0x1.b3fc95db09cfdp+0, 0x1.01abdca6af396p+1, 0x1.8998c0779ba29p+2), Pose(Vec2(0x1.a3cdff7513c29p-1, -0x1.d4d412033a676p+1), 0x1.ca9e30d40185p-1), Pose(Vec2(0x1.a3cd6da22b517p+0, -0x1.15179899a927ap+2), -0x1.4179d6a6225ap+1)},
	{262186, Spec::Super(0x1.2dc5280eadc88p+7, 0x1.35033b736215p-3, 0x1.3ee6e0e1b4414p+4, 0x1.340c3b003ac87p+2), Spec::Super(0x1.def188ddf72c6p+0, 0x1.dedc28cd13e55p+7, 0x1.ep+3, 0x1.ep+3), Pose(Vec2(-0x1.5464d86b6c248p+7, -0x1.1e06f8321dc1bp+8), -0x1.d7b20de21c53p-2), Pose(Vec2(-0x1.7133dd57ef554p+7, -0x1.1e37f7c4e9bf5p+8), -0x1.be4cb9750991cp-1)},
	{264505, Spec::Super(0x1.c6278dc905c3dp-6, 0x1.aa9868a583074p-10, 0x1.ep+3, 0x1p+1), Spec::Super(0x1.cf924b21481aep-4, 0x1.919d98ccdd1b4p-12, 0x1.ep+3, 0x1.6p+3), Pose(Vec2(0x1.7f9cfe4ace47p-4, -0x1.e0204c2bc4203p-5), -0x1.dca03a393f961p+0), Pose(Vec2(0x1.7b6f8fe7a9e94p-4, -0x1.cbd4f515d5a14p-5), -0x1.e1c74459672d8p-2)},
	{297113, Spec::Super(0x1.3ace342615c1dp-18, 0x1.6c7c4a657701cp-9, 0x1.cp+2, 0x1.cp+2), Spec::Super(0x1.e5455035e602ep-9, 0x1.eb6de9b6bab23p-18, 0x1.9fbd3f94b7ec2p+3, 0x1.2b4f11821229fp+1), Pose(Vec2(0x1.0fc5f8f758eb8p-7, 0x1.123a1480d64bap-8), 0x1.1c71d4f830dccp+1), Pose(Vec2(0x1.10bcb81a8ba06p-7, 0x1.24a0a5ffd0104p-8), -0x1.da5c770bdea3p+0)},
	{298732, Spec::Super(0x1.026e3cee8f67ep-8, 0x1.2e589b0c33e0bp-17, 0x1.4p+4, 0x1p+1), Spec::Super(0x1.797c983f22a9fp-15, 0x1.81208028e255ap-6, 0x1.2p+4, 0x1.2p+4), Pose(Vec2(-0x1.1ab134deffec6p-8, 0x1.1c610608c665bp-8), 0x1.f393393aed58cp+0), Pose(Vec2(-0x1.36ab245d618d6p-8, 0x1.e3083dc9fee61p-9), 0x1.e13452515eb3p+0)},
	{453126, Spec::Super(0x1.0de1d1be1fb25p-1, 0x1.dbf0936e4a33fp-10, 0x1.2p+4, 0x1.2p+4), Spec::Super(0x1.81be346478c25p-7, 0x1.1d4cd38df413ep+0, 0x1p+1, 0x1.8p+3), Pose(Vec2(-0x1.e8d16e221090dp+0, 0x1.2df17f8ead688p-1), -0x1.940a4f7a7aep-3), Pose(Vec2(-0x1.dd7dd8cec8df2p+0, 0x1.e93e69d407ca4p-2), -0x1.4a71925e76ef4p-1)},
	{479467, Spec::Super(0x1.3b0f3143dbddbp-1, 0x1.dc96bd95d0238p+6, 0x1p+1, 0x1.1p+4), Spec::Super(0x1.18ab2202740cfp+1, 0x1.f38d89ce785cdp+7, 0x1.9f4e17d1da8dep+3, 0x1.75e706b6762b1p+3), Pose(Vec2(0x1.4c141026add2fp+7, -0x1.04f7f473914fbp+7), 0x1.811bca0dd5f7p+1), Pose(Vec2(0x1.4750777e5edd9p+7, -0x1.eded5777add2ap+6), 0x1.072e05e2e7816p+1)},
	{493205, Spec::Super(0x1.05c547af8c17ep-12, 0x1.605baed0ddcedp-7, 0x1.3618a5c869cc7p+1, 0x1.b9c3a7f3edfd8p+3), Spec::Super(0x1.13ef1476ec91ap-4, 0x1.1d585c5446b3dp-12, 0x1.3p+4, 0x1.3p+4), Pose(Vec2(0x1.3b1d5c2952759p-5, -0x1.5d93aa8524bfbp-5), 0x1.391f1a81729p-6), Pose(Vec2(0x1.0d71eced8e3e5p-5, -0x1.5ed2230d1f8bp-5), -0x1.7d5c24a5c0261p+1)},
	{523991, Spec::Super(0x1.68f5c8f86c328p-1, 0x1.6080064299a95p+9, 0x1p+1, 0x1.2p+4), Spec::Super(0x1.7d48696a3a9a6p+2, 0x1.7214182e8ff03p-5, 0x1.369ee0cf44dcp+4, 0x1.965b54876f2b7p+3), Pose(Vec2(-0x1.2ae8664f97ec3p+6, -0x1.147ca78982fc9p+7), -0x1.68e6bb542e4d8p-2), Pose(Vec2(-0x1.444d3e51e2d41p+4, 0x1.bbcf3d53ebd08p+3), 0x1.efa853c8ac34p-5)},
	{544491, Spec::Super(0x1.08211f6958a84p-12, 0x1.0624dd2f1a9fcp-10, 0x1.4p+4, 0x1.4p+4), Spec::Super(0x1.026e3cee8f67ep-8, 0x1.2e589b0c33e0bp-17, 0x1.4p+4, 0x1p+1), Pose(Vec2(0x1.1691af360ee4cp-10, 0x1.7c3c0d291a9c2p-11), 0x1.3c786fe6b8984p+1), Pose(Vec2(0x1.253648b36a732p-9, 0x1.43b6cf89b6bb5p-13), 0x1.3c5e2cd3a602p+1)},
	{545667, Spec::Super(0x1.cb5f9aeb88ae9p+0, 0x1.850d143e2546bp-9, 0x1.4p+4, 0x1.4p+4), Spec::Super(0x1.87c65765945dcp+1, 0x1.c1ab336297564p-5, 0x1.4p+4, 0x1.8p+1), Pose(Vec2(0x1.69344c04b1a65p-2, -0x1.c1f2ed6f6efccp+0), -0x1.ddd65274f66c2p+0), Pose(Vec2(0x1.7db460dd03881p-3, -0x1.de0b39b2121adp+0), 0x1.24087ddad1212p+1)},
	{599359, Spec::Super(0x1.e2598bbd5d519p-10, 0x1.d70b7276ed21ap+0, 0x1.c3868a7d00959p+1, 0x1.d651caf97d638p+3), Spec::Super(0x1.3d098717908e1p+1, 0x1.44a56784ac99bp-9, 0x1.4p+4, 0x1.4p+4), Pose(Vec2(0x1.56081e2f35454p+2, 0x1.45196a829b32ep+1), 0x1.45ce0ac070558p+0), Pose(Vec2(0x1.4ce515a938efdp+2, 0x1.20a1a6d745449p+1), 0x1.0ce7944e5b21p+0)},
	{639813, Spec::Super(0x1.bde5eee4e1dc6p+4, 0x1.c899881562296p-6, 0x1.c0f11367fcbd8p+3, 0x1.07920277eebbp+3), Spec::Super(0x1.97dc7e4dce7aep+3, 0x1.a1a664a9c9321p-7, 0x1.6a2d6df523578p+2, 0x1.14307e91d49fp+1), Pose(Vec2(0x1.5ad57dfb1d69p+5, -0x1.121e4fdefa152p+5), -0x1.261a62ed12686p+1), Pose(Vec2(0x1.5c815a1e3faaap+5, -0x1.0d95d8068f6cep+5), 0x1.4173727bb9ab6p+1)},
	{731840, Spec::Super(0x1.2a2c3e4ff7cfep-20, 0x1.1a9782902eba8p-10, 0x1.4p+2, 0x1.ap+3), Spec::Super(0x1.6c205a932fe81p-17, 0x1.d7a33741d33dcp-10, 0x1.00c994342d6ep+1, 0x1.9ffd8c6da3c68p+3), Pose(Vec2(-0x1.6974b426d5431p-9, 0x1.64bc78bbbf1c6p-12), -0x1.657286bc9088bp+1), Pose(Vec2(-0x1.63d10c3c7ed2dp-9, 0x1.6185c1e0b8161p-12), -0x1.122d5b61eb907p+1)},
	{839032, Spec::Super(0x1.5ce10d4b039b3p-14, 0x1.54b3c6fb41859p-4, 0x1.f65fe6e9f548dp+3, 0x1.3bc1705197f34p+4), Spec::Super(0x1.ea1e3e8b7fa9p-17, 0x1.8acd8b366b341p-7, 0x1p+1, 0x1.3p+4), Pose(Vec2(0x1.72faba504137fp-5, -0x1.44761e9667148p-5), -0x1.9f70a479153c1p+0), Pose(Vec2(0x1.0afb3258d5479p-5, -0x1.53fd9a7f256eap-5), 0x1.63ee8d0bb35fp+1)},
	{851667, Spec::Super(0x1.ea1e3e8b7fa9p-17, 0x1.8acd8b366b341p-7, 0x1p+1, 0x1.3p+4), Spec::Super(0x1.f7260e820da7fp-8, 0x1.b409244b035e6p-10, 0x1.572334fd0425cp+3, 0x1.14efb4ba4bf46p+4), Pose(Vec2(0x1.8e27d8251da5ep-6, -0x1.c774f3ccb5b74p-6), 0x1.80e7db66467ap-4), Pose(Vec2(0x1.8a7482459407fp-6, -0x1.e337c014c6c15p-6), 0x1.8740b14e93aacp+1)},
	{858905, Spec::Super(0x1.1a65253643c83p-9, 0x1.212c2e4c0c109p-19, 0x1.4p+4, 0x1.4p+4), Spec::Super(0x1.0ce9b6c41a69ep-7, 0x1.135dea41a4437p-17, 0x1.ecddae694a90bp+3, 0x1.54f3e3b1138e6p+1), Pose(Vec2(0x1.07929f72e6f85p-9, -0x1.4a22af27ab061p-8), 0x1.5400f3edb625ep+1), Pose(Vec2(0x1.fbd2f4a785e83p-10, -0x1.44be00b7b91b1p-8), 0x1.0f48132829e14p-1)},
	{868632, Spec::Super(0x1.b36c403645631p+6, 0x1.c458e62132906p-2, 0x1.2b8389b244ad2p+4, 0x1.61f22b433d2b5p+3), Spec::Super(0x1.e507940ec6bddp-4, 0x1.5b9e9a520bba2p+4, 0x1.16e1b91e77c29p+1, 0x1.77d772df8b527p+3), Pose(Vec2(0x1.fc3158628590cp+1, -0x1.0784d9d15fb96p+6), 0x1.55dca4712de0cp-1), Pose(Vec2(0x1.1aaf692dfef62p+1, -0x1.1226d50e0cabfp+6), 0x1.f5026418cee8p-5)},
	{897286, Spec::Super(0x1.0624dd2f1a9fcp-10, 0x1.fd4732bd01431p-20, 0x1.1d18d45bcc6bbp+4, 0x1.678af1072b7d6p+2), Spec::Super(0x1.88d35329441afp-17, 0x1.6809c77de6b4p-8, 0x1.030d5470837ccp+1, 0x1.dd4a3673cf757p+3), Pose(Vec2(-0x1.c8d1a694fbef2p-11, 0x1.db2dbeb585e95p-9), -0x1.e392851b7146ep+0), Pose(Vec2(-0x1.86a73698d8c92p-11, 0x1.d7c2a6b4c07dp-9), -0x1.157e0407d03b4p+1)},
	{901705, Spec::Super(0x1.44e10fd4bdf4p+5, 0x1.08d020f138492p+2, 0x1.0c5e016273fb6p+4, 0x1.8be809036f41ep+1), Spec::Super(0x1.969509572695p+6, 0x1.a05713cdfa73bp-4, 0x1.dfb3ae8669c3ap+3, 0x1.659434df3078ep+1), Pose(Vec2(-0x1.007fbf84df8ecp+5, -0x1.56ebbef7960e6p+6), -0x1.77cb58613425ep+1), Pose(Vec2(-0x1.2972a670eb662p+5, -0x1.47b66bce0c258p+6), 0x1.38868b1b4cb3ep+1)},
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

TEST_CASE("needle normals: needles crossing deep inside each other get the common level to 1e-9 and the normal to 1e-6 rad")
{
	// The reference: long-double Newton on the conditions in the body frame of the particle whose
	// level set is the thinner (PolishInThinFrame, from the library's point with that particle's
	// coordinate across it matched to the other's level), held to be solved before it is used. In
	// world coordinates it would not be: at a level of 1e-30 a needle's level set is 9e-16 thick
	// at coordinates of 800 (10159). The contact's normal is the level's (its two normals opposed).
	int solved = 0;
	for (const Config& c : kDeepNeedles)
	{
		const ShapePtr a = c.a.Make(), b = c.b.Make();
		const ref::RefShape ra = c.a.Ref(), rb = c.b.Ref();
		const double size = std::min(a->BoundingRadius(), b->BoundingRadius());
		for (const auto& [pa, pb] : Neighbours(c, size))
		{
			CAPTURE(c.index);
			const stress::Posed A{ra, ref::Of(pa)}, B{rb, ref::Of(pb)};
			const LevelResult level = SolveCommonLevel(*a, pa, *b, pb);
			REQUIRE(level.Ok());
			const stress::LevelSolution want = stress::PolishInThinFrame(A, B, ref::FromVec(level.point), level.level, size);
			REQUIRE(want.ok);
			CHECK(level.level < 1e-9);
			CHECK(double(std::fabs(LD(level.level) - want.level) / want.level) <= 1e-9);
			CHECK(double(Angle(ref::FromVec(level.normal), want.normal)) <= 1e-6);
			const ContactResult r = ComputeContact(*a, pa, *b, pb);
			REQUIRE(r.Ok());
			CHECK(r.touching);
			CHECK(r.method != SolveMethod::overlapAxis);
			CHECK(double(std::fabs(LD(r.level) - want.level) / want.level) <= 1e-9);
			CHECK(double(Angle(ref::FromVec(r.normal), want.normal)) <= 1e-6);
			++solved;
		}
	}
	CHECK(solved == 7 * 25);
}
