#include "generators.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "abc_field.hpp"
#include "amrstream/error.hpp"
#include "block_emitter.hpp"
#include "block_refiner.hpp"
#include "builtin_info.hpp"
#include "cloud_field.hpp"
#include "nest_generator.hpp"
#include "rotation_field.hpp"
#include "swirl_field.hpp"

namespace amrstream::synth {

namespace {

// A sampler writing velx, vely, velz from a velocity function of the physical position.
template <typename Velocity>
BlockSampler velocitySampler(Velocity velocity) {
  return [velocity](const BlockBox&, std::span<const glm::dvec3> centres,
                    std::span<float* const> values) {
    for (std::size_t i = 0; i < centres.size(); ++i) {
      const glm::dvec3 v = velocity(centres[i]);
      for (int c = 0; c < 3; ++c) values[c][i] = float(v[c]);
    }
  };
}

bricks::AmrField build(const BuiltinOptions& options, const std::string& source,
                       const RefinementPriority& priority, const std::vector<std::string>& channels,
                       const BlockSampler& sampler, bool periodic) {
  const std::vector<Block> leaves = refineBlocks(options, source, priority);
  bricks::AmrField field =
      emitCells(leaves, generatorTransform(options), channels, sampler, source);
  field.setInfo(builtinInfo(options.levels, options.time, periodic));
  return field;
}

}  // namespace

std::vector<std::string> generatorKinds() { return {"rotation", "abc", "cloud", "swirl", "nest"}; }

bricks::AmrField generate(std::string_view kind, const BuiltinOptions& options) {
  const std::string source = fmt::format("builtin:{}", kind);
  const std::vector<std::string> velocity{"velx", "vely", "velz"};
  if (kind == "rotation")
    return build(options, source, RotationField::refinementPriority, velocity,
                 velocitySampler(RotationField::velocity), false);
  if (kind == "abc")
    return build(options, source, AbcField::refinementPriority, velocity,
                 velocitySampler(AbcField::velocity), AbcField::kPeriodic);
  if (kind == "cloud") {
    const CloudField cloud(options.seed);
    return build(
        options, source, [&](const BlockBox& box) { return cloud.refinementPriority(box); },
        {"dens", "magx", "magy", "magz"},
        [&](const BlockBox& box, std::span<const glm::dvec3> centres,
            std::span<float* const> values) { cloud.sampleBlock(box, centres, values); },
        false);
  }
  if (kind == "swirl") {
    const double t = options.time;
    return build(
        options, source,
        [t](const BlockBox& box) { return SwirlField::refinementPriority(box, t); },
        {"velx", "vely", "velz", "temp"},
        [t](const BlockBox&, std::span<const glm::dvec3> centres, std::span<float* const> values) {
          for (std::size_t i = 0; i < centres.size(); ++i) {
            const glm::dvec3 v = SwirlField::velocity(centres[i], t);
            for (int c = 0; c < 3; ++c) values[c][i] = float(v[c]);
            values[3][i] = float(SwirlField::temperature(centres[i], t));
          }
        },
        false);
  }
  if (kind == "nest") {
    NestOptions nest;
    nest.levels = options.levels;
    nest.time = options.time;
    return synth::generateNest(nest);
  }
  throw InputError(source, fmt::format("unknown generator kind '{}' (kinds: {})", kind,
                                       fmt::join(generatorKinds(), ", ")));
}

}  // namespace amrstream::synth
