#include "render/image/colour_map_controls.hpp"

namespace amrstream::render::detail {
namespace {

// Entry `index` of matplotlib's 256-entry tables (_cm_listed.py), which sit at t = index / 255.
constexpr ColourControl atEntry(int index, float r, float g, float b) {
  return {static_cast<float>(index) / 255.0f, r, g, b};
}

// Moreland's table lists 8-bit colours at t = k / 32.
constexpr ColourControl atThirtySecond(int k, int r, int g, int b) {
  return {static_cast<float>(k) / 32.0f, static_cast<float>(r) / 255.0f,
          static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f};
}

// One control per line, as published.
// clang-format off

// Every 8th entry of matplotlib's viridis and the last: linear interpolation between them stays
// within 2/255 of every entry (every 16th would be 5/255 off near the yellow end).
constexpr ColourControl kViridis[] = {
    atEntry(0, 0.267004f, 0.004874f, 0.329415f),
    atEntry(8, 0.277018f, 0.050344f, 0.375715f),
    atEntry(16, 0.282327f, 0.094955f, 0.417331f),
    atEntry(24, 0.282884f, 0.13592f, 0.453427f),
    atEntry(32, 0.278826f, 0.17549f, 0.483397f),
    atEntry(40, 0.270595f, 0.214069f, 0.507052f),
    atEntry(48, 0.258965f, 0.251537f, 0.524736f),
    atEntry(56, 0.244972f, 0.287675f, 0.53726f),
    atEntry(64, 0.229739f, 0.322361f, 0.545706f),
    atEntry(72, 0.214298f, 0.355619f, 0.551184f),
    atEntry(80, 0.19943f, 0.387607f, 0.554642f),
    atEntry(88, 0.185556f, 0.41857f, 0.556753f),
    atEntry(96, 0.172719f, 0.448791f, 0.557885f),
    atEntry(104, 0.160665f, 0.47854f, 0.558115f),
    atEntry(112, 0.149039f, 0.508051f, 0.55725f),
    atEntry(120, 0.13777f, 0.537492f, 0.554906f),
    atEntry(128, 0.127568f, 0.566949f, 0.550556f),
    atEntry(136, 0.120565f, 0.596422f, 0.543611f),
    atEntry(144, 0.120638f, 0.625828f, 0.533488f),
    atEntry(152, 0.132268f, 0.655014f, 0.519661f),
    atEntry(160, 0.157851f, 0.683765f, 0.501686f),
    atEntry(168, 0.196571f, 0.711827f, 0.479221f),
    atEntry(176, 0.24607f, 0.73891f, 0.452024f),
    atEntry(184, 0.304148f, 0.764704f, 0.419943f),
    atEntry(192, 0.369214f, 0.788888f, 0.382914f),
    atEntry(200, 0.440137f, 0.811138f, 0.340967f),
    atEntry(208, 0.515992f, 0.831158f, 0.294279f),
    atEntry(216, 0.595839f, 0.848717f, 0.243329f),
    atEntry(224, 0.678489f, 0.863742f, 0.189503f),
    atEntry(232, 0.762373f, 0.876424f, 0.137064f),
    atEntry(240, 0.845561f, 0.887322f, 0.099702f),
    atEntry(248, 0.926106f, 0.89733f, 0.104071f),
    atEntry(255, 0.993248f, 0.906157f, 0.143936f),
};

// Every 8th entry of matplotlib's magma and the last (within 2/255 of every entry).
constexpr ColourControl kMagma[] = {
    atEntry(0, 0.001462f, 0.000466f, 0.013866f),
    atEntry(8, 0.013708f, 0.011771f, 0.068667f),
    atEntry(16, 0.039608f, 0.03109f, 0.133515f),
    atEntry(24, 0.074257f, 0.052017f, 0.20266f),
    atEntry(32, 0.113094f, 0.065492f, 0.276784f),
    atEntry(40, 0.159018f, 0.068354f, 0.352688f),
    atEntry(48, 0.211718f, 0.061992f, 0.418647f),
    atEntry(56, 0.265447f, 0.060237f, 0.46184f),
    atEntry(64, 0.316654f, 0.07169f, 0.48538f),
    atEntry(72, 0.366012f, 0.090314f, 0.49796f),
    atEntry(80, 0.414709f, 0.110431f, 0.504662f),
    atEntry(88, 0.463508f, 0.129893f, 0.507652f),
    atEntry(96, 0.512831f, 0.148179f, 0.507648f),
    atEntry(104, 0.562866f, 0.165368f, 0.504692f),
    atEntry(112, 0.613617f, 0.181811f, 0.498536f),
    atEntry(120, 0.664915f, 0.198075f, 0.488836f),
    atEntry(128, 0.716387f, 0.214982f, 0.47529f),
    atEntry(136, 0.767398f, 0.233705f, 0.457755f),
    atEntry(144, 0.816914f, 0.255895f, 0.436461f),
    atEntry(152, 0.86332f, 0.283729f, 0.412403f),
    atEntry(160, 0.904281f, 0.31961f, 0.388137f),
    atEntry(168, 0.937221f, 0.364929f, 0.368567f),
    atEntry(176, 0.960949f, 0.418323f, 0.35963f),
    atEntry(184, 0.97669f, 0.476226f, 0.364466f),
    atEntry(192, 0.9867f, 0.535582f, 0.38221f),
    atEntry(200, 0.992785f, 0.594891f, 0.410283f),
    atEntry(208, 0.996096f, 0.653659f, 0.446213f),
    atEntry(216, 0.997325f, 0.711848f, 0.488154f),
    atEntry(224, 0.996898f, 0.769591f, 0.534892f),
    atEntry(232, 0.995131f, 0.827052f, 0.585701f),
    atEntry(240, 0.99244f, 0.88433f, 0.640099f),
    atEntry(248, 0.989434f, 0.94147f, 0.697519f),
    atEntry(255, 0.987053f, 0.991438f, 0.749504f),
};

// K. Moreland, "Diverging Color Maps for Scientific Visualization" (ISVC 2009), the cool-warm
// table of the expanded version.
constexpr ColourControl kCoolWarm[] = {
    atThirtySecond(0, 59, 76, 192),
    atThirtySecond(1, 68, 90, 204),
    atThirtySecond(2, 77, 104, 215),
    atThirtySecond(3, 87, 117, 225),
    atThirtySecond(4, 98, 130, 234),
    atThirtySecond(5, 108, 142, 241),
    atThirtySecond(6, 119, 154, 247),
    atThirtySecond(7, 130, 165, 251),
    atThirtySecond(8, 141, 176, 254),
    atThirtySecond(9, 152, 185, 255),
    atThirtySecond(10, 163, 194, 255),
    atThirtySecond(11, 174, 201, 253),
    atThirtySecond(12, 184, 208, 249),
    atThirtySecond(13, 194, 213, 244),
    atThirtySecond(14, 204, 217, 238),
    atThirtySecond(15, 213, 219, 230),
    atThirtySecond(16, 221, 221, 221),
    atThirtySecond(17, 229, 216, 209),
    atThirtySecond(18, 236, 211, 197),
    atThirtySecond(19, 241, 204, 185),
    atThirtySecond(20, 245, 196, 173),
    atThirtySecond(21, 247, 187, 160),
    atThirtySecond(22, 247, 177, 148),
    atThirtySecond(23, 247, 166, 135),
    atThirtySecond(24, 244, 154, 123),
    atThirtySecond(25, 241, 141, 111),
    atThirtySecond(26, 236, 127, 99),
    atThirtySecond(27, 229, 112, 88),
    atThirtySecond(28, 222, 96, 77),
    atThirtySecond(29, 213, 80, 66),
    atThirtySecond(30, 203, 62, 56),
    atThirtySecond(31, 192, 40, 47),
    atThirtySecond(32, 180, 4, 38),
};

// clang-format on

// sampleColourMap relies on this: t rises strictly from exactly 0 to exactly 1.
constexpr bool spansUnitInterval(std::span<const ColourControl> controls) {
  for (std::size_t i = 1; i < controls.size(); ++i) {
    if (!(controls[i - 1].t < controls[i].t)) return false;
  }
  return controls.size() >= 2 && controls.front().t == 0.0f && controls.back().t == 1.0f;
}
static_assert(spansUnitInterval(kViridis));
static_assert(spansUnitInterval(kMagma));
static_assert(spansUnitInterval(kCoolWarm));

}  // namespace

std::span<const ColourControl> colourControls(ColourMap map) {
  switch (map) {
    case ColourMap::Viridis:
      return kViridis;
    case ColourMap::Magma:
      return kMagma;
    case ColourMap::CoolWarm:
      return kCoolWarm;
  }
  return kViridis;
}

}  // namespace amrstream::render::detail
