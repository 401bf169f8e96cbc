#include "render/image/colour_map_controls.hpp"

namespace amrstream::render::detail {
namespace {

// Entry `index` of matplotlib's 256-entry tables (_cm_listed.py), which sit at t = index / 255.
constexpr ColourControl atEntry(int index, float r, float g, float b) {
  return {static_cast<float>(index) / 255.0f, r, g, b};
}

// matplotlib's twilight has 510 entries instead: entry `index` sits at t = index / 509.
constexpr ColourControl atTwilightEntry(int index, float r, float g, float b) {
  return {static_cast<float>(index) / 509.0f, r, g, b};
}

// Moreland's table lists 8-bit colours at t = k / 32.
constexpr ColourControl atThirtySecond(int k, int r, int g, int b) {
  return {static_cast<float>(k) / 32.0f, static_cast<float>(r) / 255.0f,
          static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f};
}

// ColorBrewer's 11 classes are 8-bit colours, at t = k / 10 here.
constexpr ColourControl atTenth(int k, int r, int g, int b) {
  return {static_cast<float>(k) / 10.0f, static_cast<float>(r) / 255.0f,
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

// Every 8th entry of matplotlib's inferno and the last (within 2/255 of every entry).
constexpr ColourControl kInferno[] = {
    atEntry(0, 0.001462f, 0.000466f, 0.013866f),
    atEntry(8, 0.013995f, 0.011225f, 0.071862f),
    atEntry(16, 0.042253f, 0.028139f, 0.141141f),
    atEntry(24, 0.081962f, 0.043328f, 0.215289f),
    atEntry(32, 0.129285f, 0.047293f, 0.290788f),
    atEntry(40, 0.183429f, 0.040329f, 0.354971f),
    atEntry(48, 0.238273f, 0.036621f, 0.396353f),
    atEntry(56, 0.290763f, 0.045644f, 0.418637f),
    atEntry(64, 0.3415f, 0.062325f, 0.429425f),
    atEntry(72, 0.391453f, 0.080927f, 0.433109f),
    atEntry(80, 0.441207f, 0.099338f, 0.431594f),
    atEntry(88, 0.491022f, 0.117179f, 0.425552f),
    atEntry(96, 0.54092f, 0.134729f, 0.415123f),
    atEntry(104, 0.590734f, 0.152563f, 0.40029f),
    atEntry(112, 0.640135f, 0.171438f, 0.381065f),
    atEntry(120, 0.688653f, 0.192239f, 0.357603f),
    atEntry(128, 0.735683f, 0.215906f, 0.330245f),
    atEntry(136, 0.780517f, 0.243327f, 0.299523f),
    atEntry(144, 0.822386f, 0.275197f, 0.266085f),
    atEntry(152, 0.860533f, 0.311892f, 0.230606f),
    atEntry(160, 0.894305f, 0.353399f, 0.193584f),
    atEntry(168, 0.923215f, 0.399359f, 0.155193f),
    atEntry(176, 0.946965f, 0.449191f, 0.115272f),
    atEntry(184, 0.965397f, 0.502249f, 0.073859f),
    atEntry(192, 0.978422f, 0.557937f, 0.034931f),
    atEntry(200, 0.985952f, 0.61575f, 0.025592f),
    atEntry(208, 0.987874f, 0.675267f, 0.065257f),
    atEntry(216, 0.984075f, 0.736087f, 0.129527f),
    atEntry(224, 0.974638f, 0.797692f, 0.206332f),
    atEntry(232, 0.960626f, 0.859069f, 0.29801f),
    atEntry(240, 0.947594f, 0.917399f, 0.410665f),
    atEntry(248, 0.954529f, 0.965896f, 0.540361f),
    atEntry(255, 0.988362f, 0.998364f, 0.644924f),
};

// Every 8th entry of matplotlib's plasma and the last, and entry 251: without it the yellow end
// would be 2.5/255 off.
constexpr ColourControl kPlasma[] = {
    atEntry(0, 0.050383f, 0.029803f, 0.527975f),
    atEntry(8, 0.132381f, 0.022258f, 0.56325f),
    atEntry(16, 0.193374f, 0.018354f, 0.59033f),
    atEntry(24, 0.248032f, 0.014439f, 0.612868f),
    atEntry(32, 0.299855f, 0.009561f, 0.631624f),
    atEntry(40, 0.35015f, 0.004382f, 0.646298f),
    atEntry(48, 0.399411f, 0.000859f, 0.656133f),
    atEntry(56, 0.447714f, 0.00208f, 0.66024f),
    atEntry(64, 0.494877f, 0.01199f, 0.657865f),
    atEntry(72, 0.54057f, 0.03495f, 0.64864f),
    atEntry(80, 0.584391f, 0.068579f, 0.632812f),
    atEntry(88, 0.625987f, 0.103312f, 0.611305f),
    atEntry(96, 0.665129f, 0.138566f, 0.585582f),
    atEntry(104, 0.701769f, 0.174005f, 0.557296f),
    atEntry(112, 0.736019f, 0.209439f, 0.527908f),
    atEntry(120, 0.76809f, 0.244817f, 0.498465f),
    atEntry(128, 0.798216f, 0.280197f, 0.469538f),
    atEntry(136, 0.826588f, 0.315714f, 0.441316f),
    atEntry(144, 0.853319f, 0.351553f, 0.413734f),
    atEntry(152, 0.878423f, 0.387932f, 0.3866f),
    atEntry(160, 0.901807f, 0.425087f, 0.359688f),
    atEntry(168, 0.923287f, 0.463251f, 0.332801f),
    atEntry(176, 0.942598f, 0.502639f, 0.305816f),
    atEntry(184, 0.959424f, 0.543431f, 0.278701f),
    atEntry(192, 0.973416f, 0.585761f, 0.25154f),
    atEntry(200, 0.984199f, 0.629718f, 0.224595f),
    atEntry(208, 0.991365f, 0.675355f, 0.198453f),
    atEntry(216, 0.994474f, 0.722691f, 0.174381f),
    atEntry(224, 0.993033f, 0.77172f, 0.154808f),
    atEntry(232, 0.986509f, 0.822401f, 0.143557f),
    atEntry(240, 0.974443f, 0.874622f, 0.144061f),
    atEntry(248, 0.956808f, 0.928152f, 0.152409f),
    atEntry(251, 0.949151f, 0.948435f, 0.152178f),
    atEntry(255, 0.940015f, 0.975158f, 0.131326f),
};

// Every 8th entry of matplotlib's cividis and the last, and entries 20, 22, 28 and 251 where the
// channels bend (red leaves 0 at entry 23, then saturates): without them, up to 5/255 off.
constexpr ColourControl kCividis[] = {
    atEntry(0, 0.0f, 0.135112f, 0.304751f),
    atEntry(8, 0.0f, 0.157932f, 0.357521f),
    atEntry(16, 0.0f, 0.178802f, 0.414764f),
    atEntry(20, 0.0f, 0.188769f, 0.439563f),
    atEntry(22, 0.0f, 0.193366f, 0.441561f),
    atEntry(24, 0.017852f, 0.198528f, 0.441248f),
    atEntry(28, 0.068968f, 0.209372f, 0.438863f),
    atEntry(32, 0.103401f, 0.220406f, 0.43579f),
    atEntry(40, 0.154261f, 0.242475f, 0.43012f),
    atEntry(48, 0.195057f, 0.264372f, 0.425924f),
    atEntry(56, 0.230871f, 0.286134f, 0.423498f),
    atEntry(64, 0.263738f, 0.307831f, 0.422789f),
    atEntry(72, 0.294669f, 0.329531f, 0.423716f),
    atEntry(80, 0.32425f, 0.351289f, 0.42625f),
    atEntry(88, 0.352892f, 0.373153f, 0.430226f),
    atEntry(96, 0.38083f, 0.395164f, 0.435653f),
    atEntry(104, 0.408226f, 0.417357f, 0.44257f),
    atEntry(112, 0.435168f, 0.439763f, 0.451134f),
    atEntry(120, 0.461616f, 0.462405f, 0.461969f),
    atEntry(128, 0.488697f, 0.485318f, 0.471008f),
    atEntry(136, 0.51792f, 0.508454f, 0.472707f),
    atEntry(144, 0.54784f, 0.531895f, 0.471704f),
    atEntry(152, 0.578236f, 0.555673f, 0.468724f),
    atEntry(160, 0.609105f, 0.579816f, 0.463638f),
    atEntry(168, 0.640352f, 0.604354f, 0.456791f),
    atEntry(176, 0.671991f, 0.629316f, 0.448018f),
    atEntry(184, 0.704037f, 0.654731f, 0.437147f),
    atEntry(192, 0.736488f, 0.680629f, 0.424028f),
    atEntry(200, 0.769353f, 0.707035f, 0.408516f),
    atEntry(208, 0.802667f, 0.733978f, 0.390153f),
    atEntry(216, 0.836429f, 0.761483f, 0.368747f),
    atEntry(224, 0.870717f, 0.789572f, 0.343333f),
    atEntry(232, 0.905589f, 0.818257f, 0.312889f),
    atEntry(240, 0.941147f, 0.84753f, 0.275815f),
    atEntry(248, 0.97778f, 0.877281f, 0.227954f),
    atEntry(251, 0.992218f, 0.888385f, 0.205468f),
    atEntry(255, 0.995737f, 0.909344f, 0.217772f),
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

// ColorBrewer's 11-class RdBu (C. Brewer, colorbrewer2.org), reversed like matplotlib's RdBu_r so
// that, as in coolwarm, low values are blue and high values red.
constexpr ColourControl kRdBu[] = {
    atTenth(0, 5, 48, 97),
    atTenth(1, 33, 102, 172),
    atTenth(2, 67, 147, 195),
    atTenth(3, 146, 197, 222),
    atTenth(4, 209, 229, 240),
    atTenth(5, 247, 247, 247),
    atTenth(6, 253, 219, 199),
    atTenth(7, 244, 165, 130),
    atTenth(8, 214, 96, 77),
    atTenth(9, 178, 24, 43),
    atTenth(10, 103, 0, 31),
};

// Every 16th entry of matplotlib's cyclic twilight and the last (within 2/255 of every entry);
// its first and last entries differ by less than 1/255.
constexpr ColourControl kTwilight[] = {
    atTwilightEntry(0, 0.8857502f, 0.8500092f, 0.8879737f),
    atTwilightEntry(16, 0.8403042f, 0.8425606f, 0.8652509f),
    atTwilightEntry(32, 0.7618691f, 0.8071195f, 0.8302665f),
    atTwilightEntry(48, 0.6672148f, 0.7595113f, 0.7986367f),
    atTwilightEntry(64, 0.5778116f, 0.7061311f, 0.7782535f),
    atTwilightEntry(80, 0.5028854f, 0.6489722f, 0.7652145f),
    atTwilightEntry(96, 0.4449325f, 0.5885056f, 0.7551311f),
    atTwilightEntry(112, 0.4053334f, 0.5245923f, 0.7445037f),
    atTwilightEntry(128, 0.3831217f, 0.4570632f, 0.7298463f),
    atTwilightEntry(144, 0.3735806f, 0.3859647f, 0.707693f),
    atTwilightEntry(160, 0.3696599f, 0.311661f, 0.6745734f),
    atTwilightEntry(176, 0.3640569f, 0.2353647f, 0.6262101f),
    atTwilightEntry(192, 0.3492451f, 0.1616148f, 0.5563484f),
    atTwilightEntry(208, 0.3168165f, 0.1038986f, 0.4605341f),
    atTwilightEntry(224, 0.2667323f, 0.07434402f, 0.3542028f),
    atTwilightEntry(240, 0.2173785f, 0.06585966f, 0.2663421f),
    atTwilightEntry(256, 0.1877448f, 0.07725159f, 0.2138745f),
    atTwilightEntry(272, 0.232663f, 0.0675571f, 0.2303762f),
    atTwilightEntry(288, 0.3007728f, 0.07661782f, 0.2617929f),
    atTwilightEntry(304, 0.3816025f, 0.09423873f, 0.2928111f),
    atTwilightEntry(320, 0.463891f, 0.1201256f, 0.3111034f),
    atTwilightEntry(336, 0.5394174f, 0.1602477f, 0.314703f),
    atTwilightEntry(352, 0.604084f, 0.2146033f, 0.3123265f),
    atTwilightEntry(368, 0.6583281f, 0.2780321f, 0.3134643f),
    atTwilightEntry(384, 0.7031625f, 0.3471872f, 0.3240891f),
    atTwilightEntry(400, 0.7387914f, 0.4205367f, 0.3491326f),
    atTwilightEntry(416, 0.7654549f, 0.4968321f, 0.3935025f),
    atTwilightEntry(432, 0.7850685f, 0.5742417f, 0.4605912f),
    atTwilightEntry(448, 0.8026053f, 0.6503379f, 0.5494169f),
    atTwilightEntry(464, 0.8245268f, 0.7226461f, 0.6531314f),
    atTwilightEntry(480, 0.8525191f, 0.7873494f, 0.7594994f),
    atTwilightEntry(496, 0.8757146f, 0.8355302f, 0.8457554f),
    atTwilightEntry(509, 0.8857116f, 0.8500219f, 0.8857254f),
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
static_assert(spansUnitInterval(kInferno));
static_assert(spansUnitInterval(kPlasma));
static_assert(spansUnitInterval(kCividis));
static_assert(spansUnitInterval(kCoolWarm));
static_assert(spansUnitInterval(kRdBu));
static_assert(spansUnitInterval(kTwilight));

}  // namespace

std::span<const ColourControl> colourControls(ColourMap map) {
  switch (map) {
    case ColourMap::Viridis:
      return kViridis;
    case ColourMap::Magma:
      return kMagma;
    case ColourMap::Inferno:
      return kInferno;
    case ColourMap::Plasma:
      return kPlasma;
    case ColourMap::Cividis:
      return kCividis;
    case ColourMap::CoolWarm:
      return kCoolWarm;
    case ColourMap::RdBu:
      return kRdBu;
    case ColourMap::Twilight:
      return kTwilight;
  }
  return kViridis;
}

}  // namespace amrstream::render::detail
