// verify-dem's pile helpers: the work check that keeps a layer-model
// comparison from comparing all-dynamic with itself.
#include <gtest/gtest.h>

#include "validate/dem/pile_runs.h"

namespace sandpic::verify {
namespace {

using PileRun = sandpic::verify::Run;  // not gtest's Test::Run

PileRun run(Layers l, double body_steps, Mode mode = Mode::Dem) {
  PileRun r;
  r.scene.mode = mode;
  r.scene.dem.layers = l;
  r.stats["backend"]["body_steps"]["all"] = body_steps;
  return r;
}

TEST(PileRuns, OfPicksTheDemRunsOfOneModel) {
  const std::vector<PileRun> runs = {run(Layers::AllDynamic, 10), run(Layers::Three, 5), run(Layers::Three, 6),
                                 run(Layers::AllDynamic, 9, Mode::Lammps)};
  ASSERT_EQ(of(runs, Layers::Three).size(), 2u);
  EXPECT_EQ(of(runs, Layers::Three)[1], &runs[2]);
  ASSERT_EQ(of(runs, Layers::AllDynamic).size(), 1u);  // not LAMMPS's
  EXPECT_EQ(of(runs, Layers::AllDynamic)[0], &runs[0]);
}

TEST(PileRuns, TheWorkCheckFailsAModelThatTookNoGrainOutOfTheSolve) {
  const PileRun a = run(Layers::AllDynamic, 1000), b = run(Layers::AllDynamic, 3000);
  const PileRun same = run(Layers::Three, 1000), same2 = run(Layers::Three, 3000);
  const VerifyCheck vacuous = work_check("three", {&same, &same2}, {&a, &b});
  EXPECT_DOUBLE_EQ(vacuous.measured, 1.0);
  EXPECT_FALSE(vacuous.pass());
  const PileRun fast = run(Layers::Three, 700), fast2 = run(Layers::Three, 1300);
  const VerifyCheck saved = work_check("three", {&fast, &fast2}, {&a, &b});
  EXPECT_DOUBLE_EQ(saved.measured, 0.5);  // summed over the runs, not averaged per run
  EXPECT_TRUE(saved.pass());
}

TEST(PileRuns, ThreeLayerIsComparedOnlyWhenListed) {
  VerifyOptions opt;
  const std::vector<Layers> both = {Layers::AllDynamic, Layers::Three}, alone = {Layers::AllDynamic};
  EXPECT_EQ(pile_models(opt), both);  // default: three,bcre
  opt.layer_models = {Layers::AllDynamic};
  EXPECT_EQ(pile_models(opt), alone);
  opt.layer_models = {Layers::Bcre};
  EXPECT_EQ(pile_models(opt), alone);
}

}  // namespace
}  // namespace sandpic::verify
