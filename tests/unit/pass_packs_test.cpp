// How the pass groups lie in the gather's rings (resolve/pass_packs): packed side by side by
// type, as many a pack as the driver holds, and a frame's groups interleaved into their places.
#include "resolve/pass_packs.h"

#include <gtest/gtest.h>

#include "taa/error.h"

#include <string>
#include <vector>

namespace taa {
namespace {

TEST(PassPacks, GroupsOfOneTypeShareAPackInGroupOrder) {
  const std::vector<bool> half{true, false, true, true, false};
  const PassPackLayout layout = packPassGroups(half, [](int, bool) { return true; });
  ASSERT_EQ(layout.packs.size(), 2u);
  EXPECT_TRUE(layout.packs[0].half);
  EXPECT_EQ(layout.packs[0].groups, (std::vector<int>{0, 2, 3}));
  EXPECT_FALSE(layout.packs[1].half);
  EXPECT_EQ(layout.packs[1].groups, (std::vector<int>{1, 4}));
  ASSERT_EQ(layout.places.size(), 5u);
  EXPECT_EQ(layout.places[3].pack, 0);
  EXPECT_EQ(layout.places[3].index, 2);
  EXPECT_EQ(layout.places[4].pack, 1);
  EXPECT_EQ(layout.places[4].index, 1);
}

TEST(PassPacks, APackHoldsNoMoreGroupsThanTheDriverTakes) {
  // The driver takes three half groups a ring and one float group.
  const std::vector<bool> half{true, true, true, true, true, true, true, false, false};
  const PassPackLayout layout =
      packPassGroups(half, [](int groups, bool isHalf) { return groups <= (isHalf ? 3 : 1); });
  ASSERT_EQ(layout.packs.size(), 5u);
  EXPECT_EQ(layout.packs[0].groups, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(layout.packs[1].groups, (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(layout.packs[2].groups, (std::vector<int>{6}));
  EXPECT_EQ(layout.packs[3].groups, (std::vector<int>{7}));
  EXPECT_EQ(layout.packs[4].groups, (std::vector<int>{8}));
  EXPECT_EQ(layout.places[6].pack, 2);
  EXPECT_EQ(layout.places[6].index, 0);
}

// Channel c of texel (x, y) of an RGBA image, half or float.
float valueAt(const TypedImage& image, int x, int y, int c) {
  const std::size_t i = (std::size_t(y) * std::size_t(image.width()) + std::size_t(x)) * 4 + c;
  return image.floats() ? image.floats()->pixels[i] : float(image.halves()->pixels[i]);
}
void setValue(TypedImage& image, int x, int y, int c, float value) {
  const std::size_t i = (std::size_t(y) * std::size_t(image.width()) + std::size_t(x)) * 4 + c;
  if (image.floats()) {
    image.floats()->pixels[i] = value;
  } else {
    image.halves()->pixels[i] = Imath::half(value);
  }
}

// A 3x2 RGBA group whose values say where they came from: 100 x row + 10 x column + channel.
TypedImage numberedGroup(SampleType type) {
  TypedImage group(3, 2, 4, type);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) {
      for (int c = 0; c < 4; ++c) setValue(group, x, y, c, float(100 * y + 10 * x + c));
    }
  }
  return group;
}

// A pack of `groups` groups of one type.
PassPackLayout::Pack packOf(int groups, bool half) {
  PassPackLayout::Pack pack;
  pack.half = half;
  for (int g = 0; g < groups; ++g) pack.groups.push_back(g);
  return pack;
}

TEST(PassPacks, AGroupsRowsLandInTheirPlaceBesideTheOthers) {
  for (const SampleType type : {SampleType::Half, SampleType::Float}) {
    const TypedImage group = numberedGroup(type);
    // Row 1 alone, as the second of a pack of two: texel x * 2 + 1.
    TypedImage band(3 * 2, 1, 4, type);
    for (int x = 0; x < 6; ++x) {
      for (int c = 0; c < 4; ++c) setValue(band, x, 0, c, -1.0f);
    }
    interleaveGroupRows(ImageView(&group), 1, 1, 1, packOf(2, type == SampleType::Half),
                        static_cast<unsigned char*>(band.data()));
    for (int x = 0; x < 3; ++x) {
      for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(valueAt(band, 2 * x, 0, c), -1.0f) << "the other group's place is left alone";
        EXPECT_EQ(valueAt(band, 2 * x + 1, 0, c), float(100 + 10 * x + c));
      }
    }
  }
}

TEST(PassPacks, RowsOutsideTheGroupOrOfAnotherTypeAreRefused) {
  const TypedImage group = numberedGroup(SampleType::Float);
  std::vector<float> band(3 * 4 * 2, 0.0f);
  auto* out = reinterpret_cast<unsigned char*>(band.data());
  EXPECT_NO_THROW(interleaveGroupRows(ImageView(&group), 0, 2, 0, packOf(1, false), out));
  EXPECT_THROW(interleaveGroupRows(ImageView(&group), 1, 2, 0, packOf(1, false), out), Error);
  EXPECT_THROW(interleaveGroupRows(ImageView(&group), 0, 1, 2, packOf(2, false), out), Error);
  EXPECT_THROW(interleaveGroupRows(ImageView(&group), 0, 1, 0, packOf(2, true), out), Error);
}

TEST(PassPacks, ADrawsDefinesNameItsPacksInTheOrderItReadsThem) {
  const std::vector<bool> half{true, false, true, false};
  const PassPackLayout layout = packPassGroups(half, [](int, bool) { return true; });
  std::vector<int> packs;
  // Groups 1..3: group 1 is the float pack's first, 2 the half pack's second, 3 the float's
  // second.
  const std::vector<std::string> defines = passPackDefines(layout, 1, 3, &packs);
  EXPECT_EQ(packs, (std::vector<int>{1, 0}));
  EXPECT_EQ(defines, (std::vector<std::string>{"#define PASS_PACKS 2",
                                                "#define PASS_PACK_OF int[](0, 1, 0)",
                                                "#define PASS_INDEX_OF int[](0, 1, 1)",
                                                "#define PASS_WIDTH_OF int[](2, 2, 2)"}));
}

}  // namespace
}  // namespace taa
