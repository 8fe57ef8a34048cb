// Test helper: the canonical networks of scenarios/{mass_spring_damper, antagonist_pair,
// musculotendon_isokinetic, millard_benchmark, chain}.yaml built in code, each by one
// function with the file's parameters (nodes, elements, loads, time span, output and solver
// settings), so that a test of the network reader can load a file and compare it with its
// function here.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/solver/simulation.h"
#include "support/canonical_actuator.h"

namespace musclesim::testing {

// One network experiment: the system, its run and its solver settings.
struct NetworkExperiment {
  NetworkSystem system;
  NetworkRunRequest request;
  SolverOptions options;

  NetworkRunResult Run() const {
    Simulation simulation;
    return simulation.Run(system, options, request);
  }
};

inline NetworkRunRequest Span(double t_end, double output_interval) {
  NetworkRunRequest request;
  request.t_start = 0.0;
  request.t_end = t_end;
  request.output_interval = output_interval;
  return request;
}

inline SolverOptions Tolerances(double rtol, double atol) {
  SolverOptions options;
  options.rtol = rtol;
  options.atol = atol;
  return options;
}

// scenarios/mass_spring_damper.yaml: a 0.5 kg mass on a spring (50 N/m, rest length 0.1 m)
// and a damper to a wall, pulled by a constant 1 N, released at rest at the spring's rest
// length (0.02 m short of the equilibrium 0.12 m). `damping` [N s/m]: 0.5 in the file
// (damping ratio 0.05, underdamped); 20 makes it overdamped (ratio 2). 2 s every 1 ms at
// rtol 1e-12, atol 1e-14.
inline constexpr double kMsdMass = 0.5, kMsdStiffness = 50.0, kMsdRestLength = 0.1, kMsdLoad = 1.0,
                        kMsdStart = 0.1, kMsdDamping = 0.5;

inline NetworkExperiment MassSpringDamper(double damping = kMsdDamping) {
  return {NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("load", kMsdMass, kMsdStart)},
                        {Element::Spring("spring", "wall", "load", kMsdStiffness, kMsdRestLength),
                         Element::Damper("damper", "wall", "load", damping)},
                        {{"load", Load::Constant(kMsdLoad)}}),
          Span(2.0, 1e-3), Tolerances(1e-12, 1e-14)};
}

// The antagonists' model: the canonical actuator's tension-length curves (f_iso, passive,
// active_length of scenarios/isometric.yaml) with a linear tension-velocity curve (n = 1)
// and v_max = 20 m/s. The canonical curve (n = 3, eps = 1e-3 m/s) is a damper of
// u f_iso f_L eps^(1/n - 1) / v_max^(1/n) near rest, 1.6e3 N s/m each here, against which no
// sensible mass oscillates; this one damps u f_iso f_L / v_max, 0.8 N s/m each.
inline ModelParams AntagonistModel() {
  ModelParams p = CanonicalModel();
  p.velocity = {20.0, 1, 1e-3};
  return p;
}

// scenarios/antagonist_pair.yaml: a 10 kg mass between two identical actuators, `flexor`
// from wall_a (x = 0) to the mass and `extensor` from the mass to wall_b (x = 0.14 m), both
// at activation 0.5. Midway (0.07 m, on the ascending limb of f_L, where co-contraction
// stiffens the pair) their tensions cancel; the mass starts at rest at `start` [m], 1e-5 m
// off that in the file. 4 s every 0.1 ms at rtol 1e-10, atol 1e-13.
inline constexpr double kPairHalfSpan = 0.07, kPairStart = 0.07001, kPairMass = 10.0,
                        kPairActivation = 0.5;

inline NetworkExperiment AntagonistPair(double start = kPairStart) {
  const auto model = std::make_shared<const TensionModel>(AntagonistModel());
  return {NetworkSystem({Node::Fixed("wall_a", 0.0), Node::Free("load", kPairMass, start),
                         Node::Fixed("wall_b", 2.0 * kPairHalfSpan)},
                        {Element::Actuator("flexor", "wall_a", "load", model,
                                           Waveform::Constant(kPairActivation)),
                         Element::Actuator("extensor", "load", "wall_b", model,
                                           Waveform::Constant(kPairActivation))}),
          Span(4.0, 1e-4), Tolerances(1e-10, 1e-13)};
}

// A musculotendon unit: `muscle` (the canonical actuator at constant `activation`) from a
// fixed wall at 0 to a 0.01 kg `junction` starting at rest at 0.091 m, a linear `tendon`
// (slack length 0.2 m, 1e4 N/m: 5 % strain at f_iso, near the 4.9 % of Millard 2012's
// tendon) from the junction to `end`, whose position follows `end_motion`; with
// `fibre_damping` > 0, a damper of that many N s/m in parallel with the muscle.
inline constexpr double kJunctionMass = 0.01, kJunctionStart = 0.091, kTendonSlack = 0.2,
                        kTendonStiffness = 1e4;

inline NetworkSystem MusculotendonUnit(Waveform end_motion, double activation,
                                       double fibre_damping) {
  std::vector<Element> elements = {
      Element::Actuator("muscle", "wall", "junction", SharedCanonicalModel(),
                        Waveform::Constant(activation)),
      Element::LinearTendon("tendon", "junction", "end", kTendonSlack, kTendonStiffness)};
  if (fibre_damping > 0.0) {
    elements.push_back(Element::Damper("fibre_damping", "wall", "junction", fibre_damping));
  }
  return NetworkSystem(
      {Node::Fixed("wall", 0.0), Node::Free("junction", kJunctionMass, kJunctionStart),
       Node::Prescribed("end", std::move(end_motion))},
      std::move(elements));
}

// scenarios/musculotendon_isokinetic.yaml: the unit fully active, its end held at 0.3 m
// (isometric) until 0.2 s, then pulled at 0.1 m/s to 0.33 m at 0.5 s (isokinetic stretch),
// then held; 0.6 s every 0.1 ms at rtol 1e-10, atol 1e-12.
inline NetworkExperiment MusculotendonIsokinetic() {
  return {MusculotendonUnit(Waveform::Ramp(0.2, 0.5, 0.3, 0.33), 1.0, 0.0), Span(0.6, 1e-4),
          Tolerances(1e-10, 1e-12)};
}

// scenarios/millard_benchmark.yaml, the benchmark of Millard et al. 2013 (J Biomech Eng
// 135:021005) adapted: the unit's end moves as 0.3 + 0.05 sin(2 pi t) m (amplitude half the
// optimal length 0.1 m, 1 Hz), with a fibre damper of 0.1 f_iso / v_max = 10 N s/m (the
// damped-equilibrium model's beta = 0.1), at a constant `activation` (1.0 in the file; the
// benchmark sweeps 0 to 1). One period, 1 s, every 1 ms at rtol 1e-8, atol 1e-12.
inline constexpr double kMillardFibreDamping = 10.0;

inline NetworkExperiment MillardBenchmark(double activation = 1.0) {
  return {MusculotendonUnit(Waveform::Sine(0.3, 0.05, 1.0), activation, kMillardFibreDamping),
          Span(1.0, 1e-3), Tolerances(1e-8, 1e-12)};
}

// scenarios/chain.yaml (n = 10): `n` segments in series from a fixed wall, segment i an
// actuator `muscle<i>` (canonical, activation 0.2) with a damper `damper<i>` (10 N s/m) in
// parallel, from node i - 1 to node i (node 0 the wall), every node a 0.01 kg mass starting
// at rest i * 0.145 m from the wall; a constant 100 N pulls the last node. The segments
// settle at the length where T(l, 0, 0.2) = 100 N (0.1506 m, where the passive element
// carries most of it). Damping acts on each segment as its stiffness does, so every mode
// of the chain creeps back at dT/dl / (c - dT/dv) = 9.2e3 / 563 = 16 /s near rest, whatever
// n: 5 s every 0.5 s at rtol 1e-8, atol 1e-12.
inline constexpr double kChainMass = 0.01, kChainStart = 0.145, kChainActivation = 0.2,
                        kChainDamping = 10.0, kChainLoad = 100.0;

// `prefix` followed by i (appended: GCC 12 warns falsely about "n" + std::to_string(i))
inline std::string Numbered(std::string prefix, int i) {
  prefix += std::to_string(i);
  return prefix;
}

inline std::string ChainNode(int i) { return i == 0 ? "wall" : Numbered("n", i); }

inline NetworkExperiment Chain(int n, LinearSolverKind linear_solver = LinearSolverKind::kAuto) {
  const auto model = SharedCanonicalModel();
  std::vector<Node> nodes = {Node::Fixed("wall", 0.0)};
  std::vector<Element> elements;
  for (int i = 1; i <= n; ++i) {
    // 145 i / 1000 rounds once, to the double the file's decimal i * 0.145 reads as
    nodes.push_back(Node::Free(ChainNode(i), kChainMass, 145.0 * i / 1000.0));
    elements.push_back(Element::Actuator(Numbered("muscle", i), ChainNode(i - 1), ChainNode(i),
                                         model, Waveform::Constant(kChainActivation)));
    elements.push_back(
        Element::Damper(Numbered("damper", i), ChainNode(i - 1), ChainNode(i), kChainDamping));
  }
  SolverOptions options = Tolerances(1e-8, 1e-12);
  options.linear_solver = linear_solver;
  return {NetworkSystem(std::move(nodes), std::move(elements),
                        {{ChainNode(n), Load::Constant(kChainLoad)}}),
          Span(5.0, 0.5), options};
}

}  // namespace musclesim::testing
