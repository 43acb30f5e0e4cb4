// SPDX-License-Identifier: GPL-3.0-or-later
//
// Joints with cohesion and tensile strength (contact issue: "cohesion/
// tensile strength of joints where the material gives them"). Faces that
// touch when the run starts are bonded; a bond breaks for good when its
// normal spring pulls harder than tensile strength times contact length,
// or its shear spring exceeds cohesion times length plus friction times
// the normal force (doc/contact.md, "Bonded joints").
//
//  - A 1 m x 1 m block hangs under a fixed roof, held by the joint's
//    tension (cohesion as large as the tensile strength: without it,
//    Mohr-Coulomb leaves a joint in tension no shear strength, and the
//    block's Poisson contraction alone would break it). The bonded contact
//    lengths add up to the joint's 1 m (both sides have vertices on it, on
//    non-matching meshes). With a tensile strength of twice the block's weight
//    per metre it stays up (displacement below 1 mm after 0.3 s); with half of
//    it the bonds break in the first step and the block falls freely: g t^2 / 2
//    within 1 % at t = 0.3 s.
//  - The block of prm/sliding_block.prm (30 degree incline, friction angle
//    20 degrees), bonded with cohesion c and tensile strength c. As a rigid
//    block it needs c = 2.36 kPa to stay. With 1 kPa it breaks loose and
//    slides g (sin a - cos a tan phi) t^2 / 2, within 1 % at t = 0.5 s.
//    The elastic block loads the ends of the joint most, and gravity
//    switched on at t = 0 overshoots: bonds break from the ends inwards
//    for c = 5 kPa, and hold at 10 and 20 kPa on the example's rigid
//    incline (printed, doc/contact.md); with 40 kPa the block creeps less
//    than 0.1 mm in 0.5 s.
//
// No contact penetrates deeper than the tolerance in any run.

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

namespace
{
  const double g = 9.81;

  const std::string hanging_scene = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 1e-3
  set End time        = 0.3
  set Maximum displacement ratio = 0.01
end
subsection Contact
  set Penalty factor = 10
end
subsection Materials
  set Names = rock
  subsection rock
    set Density = 2500
    set Young's modulus = 10e9
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle   = 30
    set Tensile strength = {tension}
    set Cohesion         = {tension}
  end
end
subsection Geometry
  set Blocks = roof, block
  subsection roof
    set Outer boundary = 0, 1; 2, 1; 2, 2; 0, 2
    set Material = rock
    set Mesh size = 0.25
  end
  subsection block
    set Outer boundary = 0.6, 0; 1.6, 0; 1.6, 1; 0.6, 1
    set Material = rock
    set Mesh size = 0.25
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = top
  subsection top
    set Type = fixed
    set Segments = 0, 2, 2, 2
  end
end
subsection Output
  set Measure points = 1.1, 0.5
end
)";

  struct Result
  {
    double       displacement; // of the measure point, along the motion
    double       bonded_length_at_start;
    unsigned int bonded_at_end;
    double       max_penetration;
    double       tolerance;
  };

  Result
  run(const std::string         &text,
      const double               end_time,
      const dealii::Tensor<1, 2> direction)
  {
    const auto         parameters = read_parameters(text, "bonded_joints");
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    Result     result{};
    const auto box   = simulator.get_mesh().bounding_box();
    result.tolerance = parameters.contact.max_penetration_ratio * 0.5 *
                       (box.second[1] - box.first[1]); // as the Simulator's
    while (simulator.get_time() < end_time - 1e-12)
      {
        simulator.do_time_step();
        const auto &c = simulator.get_contacts().get_statistics();
        if (simulator.get_step_number() == 1)
          result.bonded_length_at_start = c.bonded_length;
        result.bonded_at_end = c.n_bonded;
        result.max_penetration =
          std::max(result.max_penetration, c.max_penetration);
      }
    result.displacement =
      simulator.get_measure_histories()[0].back().displacement * direction;
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);

  // The hanging block: weight per metre of joint rho g A / L.
  const double weight = 2500 * g * 1. * 1. / 1.;
  std::cout << "hanging block, weight per metre of joint " << weight << " N/m"
            << std::endl;
  for (const double factor : {2., 0.5})
    {
      const Result r =
        run(substitute(hanging_scene,
                       {{"tension", std::to_string(factor * weight)}}),
            0.3,
            Tensor<1, 2>({0., -1.}));
      std::cout << "  tensile strength " << factor
                << " x weight: bonded length at start "
                << r.bonded_length_at_start << " m, bonded contacts at end "
                << r.bonded_at_end << ", fall " << r.displacement
                << " m, max penetration " << r.max_penetration
                << " m (tolerance " << r.tolerance << " m)" << std::endl;
      const std::string key = std::string("bonded_joints.hanging_") +
                              (factor > 1 ? "strong." : "weak.");
      record(key + "bonded_length", r.bonded_length_at_start, 6);
      record(key + "bonded_at_end", r.bonded_at_end);
      record(key + "fall", r.displacement * (factor > 1 ? 1e6 : 1.), 4);
      if (factor > 1)
        record(key + "met",
               met(std::abs(r.bonded_length_at_start - 1.) < 1e-9 &&
                   std::abs(r.displacement) < 1e-3 && r.bonded_at_end > 0));
      else
        {
          const double error = r.displacement / (0.5 * g * 0.3 * 0.3) - 1;
          record(key + "error", std::abs(error), 1);
          record(key + "met",
                 met(r.bonded_at_end == 0 && std::abs(error) < 1e-2));
        }
      check(r.max_penetration <= r.tolerance, "penetration");
      if (factor > 1)
        {
          check(std::abs(r.bonded_length_at_start - 1.) < 1e-9,
                "bonded lengths add up to the joint's length");
          check(std::abs(r.displacement) < 1e-3 && r.bonded_at_end > 0,
                "a strong bond holds the block");
        }
      else
        {
          const double free_fall = 0.5 * g * 0.3 * 0.3;
          const double error     = r.displacement / free_fall - 1;
          std::cout << "    free fall " << free_fall << " m, error "
                    << 100 * error << " %" << std::endl;
          check(r.bonded_at_end == 0 && std::abs(error) < 1e-2,
                "a weak bond breaks and the block falls freely");
        }
    }

  // The cohesive incline.
  const double slope = 30. * M_PI / 180., phi = 20. * M_PI / 180.;
  const double needed =
    2600 * g * 0.5 * (std::sin(slope) - std::cos(slope) * std::tan(phi));
  std::cout << "incline: cohesion needed to hold the block " << needed << " Pa"
            << std::endl;
  record("bonded_joints.needed", needed / 1e3, 3);
  const Tensor<1, 2> down_slope({-std::cos(slope), -std::sin(slope)});
  for (const double cohesion : {5000., 10000., 20000., 40000., 1000.})
    {
      std::string       text = read_example("sliding_block");
      const std::string line = "    set Friction angle = 20\n";
      check(text.find(line) != std::string::npos,
            "prm/sliding_block.prm has the friction line");
      text.replace(text.find(line),
                   line.size(),
                   line + "    set Cohesion = " + std::to_string(cohesion) +
                     "\n    set Tensile strength = " +
                     std::to_string(cohesion) + "\n");
      text += "subsection Control\n  set End time = 0.5\nend\n";
      const Result r = run(text, 0.5, down_slope);
      std::cout << "  cohesion " << cohesion << " Pa: bonded length at start "
                << r.bonded_length_at_start << " m, bonded contacts at end "
                << r.bonded_at_end << ", slide " << r.displacement
                << " m, max penetration " << r.max_penetration
                << " m (tolerance " << r.tolerance << " m)" << std::endl;
      const std::string key =
        "bonded_joints.incline_" + std::to_string(int(cohesion / 1000)) + ".";
      record(key + "bonded_at_end", r.bonded_at_end);
      record(key + "slide", r.displacement, 4);
      record(key + "creep", r.displacement * 1e6, 2);
      if (cohesion < needed)
        {
          const double error =
            r.displacement /
              (0.5 * g * (std::sin(slope) - std::cos(slope) * std::tan(phi)) *
               0.25) -
            1;
          record(key + "error", 100 * error, 2);
          record(key + "met",
                 met(r.bonded_at_end == 0 && std::abs(error) < 1e-2));
        }
      else if (cohesion >= 40000.)
        record(key + "met",
               met(std::abs(r.displacement) < 1e-4 && r.bonded_at_end > 0));
      check(r.max_penetration <= r.tolerance, "penetration");
      if (cohesion > needed)
        {
          check(std::abs(r.bonded_length_at_start - 1.) < 1e-9 ||
                  cohesion < 40000.,
                "bonded lengths add up to the joint's length");
          // Shear gathers at the joint's ends (the bodies are elastic)
          // and gravity switched on at t = 0 overshoots its static load:
          // the bonds at the ends break first. 5-20 kPa break step by
          // step (printed); 40 kPa must hold.
          if (cohesion >= 40000.)
            check(std::abs(r.displacement) < 1e-4 && r.bonded_at_end > 0,
                  "cohesion holds the block");
        }
      else
        {
          const double slide =
            0.5 * g * (std::sin(slope) - std::cos(slope) * std::tan(phi)) *
            0.5 * 0.5;
          const double error = r.displacement / slide - 1;
          std::cout << "    expected slide " << slide << " m, error "
                    << 100 * error << " %" << std::endl;
          check(r.bonded_at_end == 0 && std::abs(error) < 1e-2,
                "a weak bond breaks and the block slides");
        }
    }
  std::cout << "OK" << std::endl;
}
