// Channel kinds by pass name and rule, and the plan that resolves them (issue 21).
#include "resolve/pass_plan.h"

#include <gtest/gtest.h>

#include "io/channel_kinds.h"
#include "taa/error.h"

namespace taa {
namespace {

using io::ChannelKind;
using io::channelKind;

TEST(ChannelKinds, CyclesPassNamesHaveTheirKinds) {
  EXPECT_EQ(channelKind("ViewLayer.Combined.R", {}), ChannelKind::Light);
  EXPECT_EQ(channelKind("ViewLayer.DiffDir.G", {}), ChannelKind::Light);
  EXPECT_EQ(channelKind("ViewLayer.Shadow.B", {}), ChannelKind::Light);
  EXPECT_EQ(channelKind("ViewLayer.GlossCol.B", {}), ChannelKind::Factor);
  EXPECT_EQ(channelKind("ViewLayer.Normal.X", {}), ChannelKind::Normal);
  EXPECT_EQ(channelKind("ViewLayer.UV.U", {}), ChannelKind::Average);
  EXPECT_EQ(channelKind("ViewLayer.Position.Z", {}), ChannelKind::Average);
  EXPECT_EQ(channelKind("ViewLayer.Depth.Z", {}), ChannelKind::Nearest);
  EXPECT_EQ(channelKind("ViewLayer.IndexOB.X", {}), ChannelKind::Nearest);
  EXPECT_EQ(channelKind("ViewLayer.Vector.W", {}), ChannelKind::Nearest);
  EXPECT_EQ(channelKind("ViewLayer.CryptoObject01.r", {}), ChannelKind::Cryptomatte);
  // Unknown passes: colour components are light, anything else data.
  EXPECT_EQ(channelKind("ViewLayer.my_light_group.R", {}), ChannelKind::Light);
  EXPECT_EQ(channelKind("ViewLayer.my_data.X", {}), ChannelKind::Nearest);
  EXPECT_EQ(channelKind("Z", {}), ChannelKind::Nearest);
}

TEST(ChannelKinds, TheFirstMatchingRuleWins) {
  const std::vector<io::ChannelKindRule> rules = {io::parseChannelKindRule("*.Normal.*=average"),
                                                  io::parseChannelKindRule("*=drop")};
  EXPECT_EQ(channelKind("ViewLayer.Normal.X", rules), ChannelKind::Average);
  EXPECT_EQ(channelKind("ViewLayer.DiffDir.R", rules), ChannelKind::Drop);
  EXPECT_EQ(io::parseChannelKindRule("a=b=light").pattern, "a=b");
  EXPECT_THROW(io::parseChannelKindRule("=light"), Error);
  EXPECT_THROW(io::parseChannelKindRule("x=bright"), Error);
}

TEST(ChannelKinds, LightPassesFindTheirFactor) {
  EXPECT_EQ(io::factorChannelOf("ViewLayer.DiffDir.R"), "ViewLayer.DiffCol.R");
  EXPECT_EQ(io::factorChannelOf("ViewLayer.GlossInd.B"), "ViewLayer.GlossCol.B");
  EXPECT_EQ(io::factorChannelOf("diffuse_direct.G"), "diffuse_albedo.G");
  EXPECT_EQ(io::factorChannelOf("ViewLayer.VolumeDir.R"), "");
  EXPECT_EQ(io::factorChannelOf("ViewLayer.Emit.R"), "");
}

// One pixel: light x factor summed and divided by the summed factor gives a light whose product
// with the resolved factor is the resolved light; normals come back unit length; nearest
// channels are t's own.
TEST(PassPlan, ProductsAreSummedAndDividedAndNormalsRenormalised) {
  const std::vector<std::string> names = {"L.DiffDir.R", "L.DiffCol.R", "L.Normal.X", "L.Normal.Y",
                                          "L.Normal.Z", "L.IndexOB.X"};
  const std::vector<OIIO::TypeDesc> formats(names.size(), OIIO::TypeHalf);
  const PassPlan plan = planPasses(names, formats, {});
  ASSERT_EQ(plan.groups(), 2);  // DiffDir x DiffCol, DiffCol, Normal X Y Z
  EXPECT_EQ(plan.factor[0], 1);
  EXPECT_TRUE(plan.halfGroups[0]);  // half channels: half rings, products too
  EXPECT_TRUE(plan.halfGroups[1]);
  const PassPlan floatPlan =
      planPasses(names, std::vector<OIIO::TypeDesc>(names.size(), OIIO::TypeFloat), {});
  EXPECT_FALSE(floatPlan.halfGroups[0]);
  EXPECT_EQ(plan.keptCount, 1);
  EXPECT_TRUE(plan.halfOrFloat && floatPlan.halfOrFloat);  // packed in their types when finished
  std::vector<OIIO::TypeDesc> withUint = formats;
  withUint.back() = OIIO::TypeUInt;  // an ID as uint: the finished passes go the float way
  EXPECT_FALSE(planPasses(names, withUint, {}).halfOrFloat);

  // Two samples, equal weights: light 0.2 x colour 0.5 and 0.6 x colour 1.0.
  Image a(1, 1, 6), b(1, 1, 6);
  a.pixels = {0.2f, 0.5f, 1.0f, 0.0f, 0.0f, 3.0f};
  b.pixels = {0.6f, 1.0f, 0.0f, 1.0f, 0.0f, 4.0f};
  // Half channels are packed as half (the ring's type), products rounded once.
  const std::vector<TypedImage> halves = packPasses(a, plan).groups;
  ASSERT_EQ(halves.size(), 2u);
  ASSERT_EQ(halves[0].type(), SampleType::Half);
  EXPECT_EQ(halves[0].toFloat().pixels[0], float(Imath::half(0.2f * 0.5f)));
  EXPECT_EQ(halves[1].toFloat().pixels[3], 0.0f);  // the unused slot
  const PackedPasses pa = packPasses(a, floatPlan), pb = packPasses(b, floatPlan);
  const std::vector<TypedImage>&ga = pa.groups, &gb = pb.groups;
  ASSERT_EQ(ga[0].type(), SampleType::Float);
  PassSums sums;
  for (int g = 0; g < 2; ++g) {
    Image sum(1, 1, 4);
    for (int c = 0; c < 4; ++c) {
      sum.pixels[c] = 0.5f * (ga[g].floats()->pixels[c] + gb[g].floats()->pixels[c]);
    }
    sums.groups.emplace_back(std::move(sum));
  }
  const Image out = finishPasses(sums, pa.kept, floatPlan);
  const float light = 0.5f * (0.2f * 0.5f + 0.6f * 1.0f);
  EXPECT_FLOAT_EQ(out.pixels[1], 0.75f);
  EXPECT_FLOAT_EQ(out.pixels[0] * out.pixels[1], light);
  EXPECT_FLOAT_EQ(out.pixels[2], std::sqrt(0.5f));
  EXPECT_FLOAT_EQ(out.pixels[3], std::sqrt(0.5f));
  EXPECT_EQ(out.pixels[5], 3.0f);
}


// A render's half and float passes interleave in file order (Cycles: AO, DiffCol, ... half,
// Normal, Position float, Shadow, Trans* half, UV float). The half values are grouped ahead of
// the float ones, so only the groups that need float are float; each channel still finds its
// own value.
TEST(PassPlan, HalfValuesFillWholeGroupsAheadOfFloatOnes) {
  const std::vector<std::string> names = {"L.AO.R",       "L.AO.G",       "L.AO.B",
                                          "L.Normal.X",   "L.Normal.Y",   "L.Normal.Z",
                                          "L.Shadow.R",   "L.Shadow.G",   "L.Shadow.B",
                                          "L.Position.X", "L.Position.Y", "L.Emit.R",
                                          "L.Emit.G"};
  const auto H = OIIO::TypeHalf, F = OIIO::TypeFloat;
  const std::vector<OIIO::TypeDesc> formats = {H, H, H, F, F, F, H, H, H, F, F, H, H};
  const PassPlan plan = planPasses(names, formats, {});
  // 8 half values, 5 float: 2 half groups and 2 float ones (in file order: 4 groups, 1 half).
  ASSERT_EQ(plan.groups(), 4);
  EXPECT_EQ(plan.halfGroups, (std::vector<bool>{true, true, false, false}));
  for (std::size_t c = 0; c < names.size(); ++c) {
    ASSERT_GE(plan.value[c], 0) << names[c];
    EXPECT_EQ(plan.valueChannel[std::size_t(plan.value[c])], int(c)) << names[c];
    EXPECT_EQ(plan.value[c] < 8, formats[c] == H) << names[c];
  }
  // The values come back to their channels: each channel's value is its own index.
  Image frame(1, 1, int(names.size()));
  for (std::size_t c = 0; c < names.size(); ++c) frame.pixels[c] = 0.25f * float(c + 1);
  const PackedPasses packed = packPasses(frame, plan);
  PassSums sums;
  for (const TypedImage& group : packed.groups) sums.groups.push_back(group.toFloat());
  const Image out = finishPasses(sums, packed.kept, plan);
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (c >= 3 && c <= 5) continue;  // the normal is renormalised
    EXPECT_EQ(out.pixels[c], frame.pixels[c]) << names[c];
  }
}

}  // namespace
}  // namespace taa
