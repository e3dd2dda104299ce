#include <frictional_contact/base/input.h>
#include <frictional_contact/base/plugins.h>
#include <frictional_contact/material/j2_plasticity.h>
#include <frictional_contact/material/spectral_decomposition.h>

#include <cmath>

namespace FrictionalContact
{
  namespace MaterialLaws
  {
    namespace
    {
      using Tensor3 = SymmetricTensor<2, 3>;

      /// The 3D strain of the element: the deviator of the in-plane strain
      /// @p strain (its out-of-plane part zero in plane strain) and the
      /// volumetric strain @p theta.
      template <int dim>
      Tensor3
      strain_3d(const SymmetricTensor<2, dim> &strain, const double theta)
      {
        Tensor3 embedded;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            embedded[i][j] = strain[i][j];
        return deviator(embedded) + theta / 3. * unit_symmetric_tensor<3>();
      }
    } // namespace



    template <int dim>
    void
    J2Plasticity<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Yield stress",
                        "1",
                        Patterns::Anything(),
                        "sigma_y: the stress at which the material first "
                        "yields, in Yield stress measure (force/area, > 0). "
                        "Like every entry of Material, one value for all "
                        "bodies or one per body.");
      prm.declare_entry("Yield stress measure",
                        "von Mises",
                        Patterns::Anything(),
                        "von Mises: Yield stress is the uniaxial yield stress, "
                        "sqrt(3/2) |dev sigma| <= sigma_y. deviator norm: "
                        "|dev sigma| <= Yield stress, step-42's sigma_0.");
      prm.declare_entry("Isotropic hardening modulus",
                        "0",
                        Patterns::Anything(),
                        "H_iso: the slope that isotropic hardening adds to the "
                        "uniaxial stress against the plastic strain (force/"
                        "area, >= 0; 0 with no kinematic hardening is perfect "
                        "plasticity).");
      prm.declare_entry("Isotropic hardening ratio",
                        "",
                        Patterns::Anything(),
                        "step-42's gamma, in [0, 1), instead of the modulus: "
                        "the part of the trial stress beyond the yield surface "
                        "a single step keeps, H_iso = 3 G gamma / (1 - gamma). "
                        "Empty: the modulus decides.");
      prm.declare_entry("Hardening",
                        "linear",
                        Patterns::Anything(),
                        "The isotropic hardening law, sigma_y of the equivalent "
                        "plastic strain ep. linear: Yield stress + H_iso ep. "
                        "Voce: Yield stress + (Saturation yield stress - Yield "
                        "stress)(1 - exp(-Saturation rate ep)) + H_iso ep. flow "
                        "curve: the points of Flow curve, piecewise linear and "
                        "constant past the last (Yield stress and the hardening "
                        "modulus are then not used).");
      prm.declare_entry("Saturation yield stress",
                        "1",
                        Patterns::Anything(),
                        "sigma_inf of Voce hardening: the yield stress it "
                        "saturates at (force/area, > 0).");
      prm.declare_entry("Saturation rate",
                        "0",
                        Patterns::Anything(),
                        "delta of Voce hardening: how fast it saturates, per "
                        "unit of equivalent plastic strain (>= 0).");
      prm.declare_entry("Flow curve",
                        "",
                        Patterns::Anything(),
                        "The measured flow curve of Hardening = flow curve: "
                        "points 'plastic strain yield stress' separated by ',', "
                        "e.g. '0 400, 0.05 480, 0.3 560': plastic strains from "
                        "0, increasing, yield stresses > 0.");
      prm.declare_entry("Kinematic hardening modulus",
                        "0",
                        Patterns::Anything(),
                        "H_kin: the slope that kinematic (Prager) hardening "
                        "adds to the uniaxial stress against the plastic "
                        "strain (force/area, >= 0): the yield surface moves "
                        "with the back stress (the Bauschinger effect).");
    }



    template <int dim>
    void
    J2Plasticity<dim>::parse_parameters(const BodyEntries &material,
                                        const BodyEntries &own)
    {
      MaterialModel<dim>::parse_parameters(material, own);
      const ElasticConstants<dim> &elastic = this->elastic();
      if (dim == 2 && elastic.plane_stress)
        Input::fail(material.path_of("Two-dimensional model"), "plane stress",
                    "plane strain (J2 plasticity in plane stress is not "
                    "supported here; the body '" + own.body() + "' has it)");
      const std::string measure = own.get("Yield stress measure");
      if (measure != "von Mises" && measure != "deviator norm")
        Input::fail(own.path_of("Yield stress measure"), measure,
                    "'von Mises' or 'deviator norm'");
      double yield_stress = own.get_number("Yield stress");
      if (!(yield_stress > 0))
        Input::fail(own.path_of("Yield stress"), own.get("Yield stress"),
                    "a positive stress");
      if (measure == "deviator norm")
        yield_stress *= std::sqrt(1.5);
      double isotropic_hardening = own.get_number("Isotropic hardening modulus");
      kinematic_hardening        = own.get_number("Kinematic hardening modulus");
      for (const char *entry : {"Isotropic hardening modulus", "Kinematic hardening modulus"})
        if (!(own.get_number(entry) >= 0))
          Input::fail(own.path_of(entry), own.get(entry), "a modulus >= 0");
      if (elastic.finite_strain && kinematic_hardening != 0)
        Input::fail(own.path_of("Kinematic hardening modulus"),
                    own.get("Kinematic hardening modulus"),
                    "0 at finite strain (the body '" + own.body() +
                      "' is at finite strain, whose J2 law hardens "
                      "isotropically only)");
      if (const std::string ratio = own.get("Isotropic hardening ratio"); !ratio.empty())
        {
          const double gamma = own.get_number("Isotropic hardening ratio");
          if (!(gamma >= 0 && gamma < 1) || isotropic_hardening != 0)
            Input::fail(own.path_of("Isotropic hardening ratio"), ratio,
                        "a ratio in [0, 1), and then no Isotropic hardening "
                        "modulus");
          isotropic_hardening = 3. * elastic.shear_modulus * gamma / (1. - gamma);
        }
      const std::string law = own.get("Hardening");
      if (law == "linear")
        hardening = IsotropicHardening::linear(yield_stress, isotropic_hardening);
      else if (law == "Voce")
        {
          const double saturation = own.get_number("Saturation yield stress");
          const double rate       = own.get_number("Saturation rate");
          if (!(saturation > 0))
            Input::fail(own.path_of("Saturation yield stress"),
                        own.get("Saturation yield stress"), "a positive stress");
          if (!(rate >= 0))
            Input::fail(own.path_of("Saturation rate"), own.get("Saturation rate"),
                        "a rate >= 0");
          hardening =
            IsotropicHardening::voce(yield_stress, saturation, rate, isotropic_hardening);
        }
      else if (law == "flow curve")
        {
          const std::string text = own.get("Flow curve");
          std::vector<std::pair<double, double>> points;
          for (const std::string &item : Utilities::split_string_list(text, ','))
            {
              const std::vector<std::string> pair = Utilities::split_string_list(item, ' ');
              std::vector<double> numbers;
              for (const std::string &word : pair)
                if (!word.empty())
                  numbers.push_back(Input::parse_number(
                    own.path_of("Flow curve"), word,
                    "points 'plastic strain yield stress' separated by ','"));
              if (numbers.size() != 2)
                Input::fail(own.path_of("Flow curve"), text,
                            "points 'plastic strain yield stress' separated by "
                            "',' ('" + item + "' is not two numbers)");
              points.emplace_back(numbers[0], numbers[1]);
            }
          if (const std::string problem = IsotropicHardening::flow_curve_problem(points);
              !problem.empty())
            Input::fail(own.path_of("Flow curve"), text,
                        "a flow curve from plastic strain 0 on, its plastic "
                        "strains increasing and its yield stresses > 0 (" +
                          problem + ")");
          hardening = IsotropicHardening::flow_curve(std::move(points));
        }
      else
        Input::fail(own.path_of("Hardening"), law, "'linear', 'Voce' or 'flow curve'");
      tangent_of_strain(elastic.bulk_modulus_3d,
                        elastic.shear_modulus,
                        0.,
                        SymmetricTensor<2, 3>(),
                        elastic_response);
    }



    template <int dim>
    void
    J2Plasticity<dim>::evaluate(const SymmetricTensor<2, dim> &strain,
                                const double                   volumetric_strain,
                                const double                  *history,
                                const bool                     with_tangent,
                                MaterialResponse<dim>         &response,
                                double                        *new_history) const
    {
      if (this->elastic().finite_strain)
        {
          evaluate_finite_strain(
            strain, volumetric_strain, history, with_tangent, response, new_history);
          return;
        }
      const double  mu    = this->elastic().shear_modulus;
      const double  kappa = this->elastic().bulk_modulus_3d;
      const Tensor3 I     = unit_symmetric_tensor<3>();

      // The trial state: the strain beyond the committed plastic strain,
      // elastic.
      const Tensor3 plastic_before = read_history_tensor(history);
      const double  alpha_before   = history[6];
      const Tensor3 back_before    = read_history_tensor(history + 7);
      const Tensor3 total          = strain_3d(strain, volumetric_strain);
      const Tensor3 trial          = 2. * mu * (deviator(total) - plastic_before);
      const RadialReturn flow_step = radial_return(trial - back_before, alpha_before);
      const double       step      = flow_step.step;
      const Tensor3     &n         = flow_step.n;
      response.plastic             = step > 0;
      response.at_yield            = flow_step.at_yield;
      const Tensor3 stress = trial - 2. * mu * step * n + kappa * volumetric_strain * I;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          response.stress[i][j] = stress[i][j];
      response.volumetric_stress   = trace(stress) / 3.;
      response.out_of_plane_stress = dim == 2 ? stress[2][2] : 0.;

      if (new_history != nullptr)
        {
          write_history_tensor(plastic_before + step * n, new_history);
          new_history[6] = alpha_before + std::sqrt(2. / 3.) * step;
          write_history_tensor(back_before + 2. / 3. * kinematic_hardening * step * n,
                       new_history + 7);
        }
      if (!with_tangent)
        return;
      if (step == 0)
        {
          response.stress_by_strain                       = elastic_response.stress_by_strain;
          response.stress_by_volumetric_strain            = elastic_response.stress_by_volumetric_strain;
          response.volumetric_stress_by_strain            = elastic_response.volumetric_stress_by_strain;
          response.volumetric_stress_by_volumetric_strain =
            elastic_response.volumetric_stress_by_volumetric_strain;
          return;
        }
      tangent_of_strain(kappa, flow_step.shear, flow_step.flow, n, response);
    }



    template <int dim>
    RadialReturn
    J2Plasticity<dim>::radial_return(const SymmetricTensor<2, 3> &relative,
                                     const double                 alpha_before) const
    {
      const double mu     = this->elastic().shear_modulus;
      const double norm   = relative.norm();
      const double radius = std::sqrt(2. / 3.) * hardening.yield_stress(alpha_before);
      const double excess = norm - radius;
      RadialReturn result;
      result.at_yield = excess > -1e-10 * radius;
      result.shear    = mu;
      if (!(excess > 0))
        return result;
      result.n    = relative / norm;
      result.step = return_step(norm, alpha_before, mu);
      // The consistent tangent (Simo and Hughes, box 3.2): 2 mu theta P_dev
      // - 2 mu theta_bar n (x) n on the deviator.
      const double theta = 1. - 2. * mu * result.step / norm;
      const double slope = hardening.slope(alpha_before + std::sqrt(2. / 3.) * result.step);
      const double theta_bar =
        1. / (1. + (slope + kinematic_hardening) / (3. * mu)) - (1. - theta);
      result.shear = mu * theta;
      result.flow  = -2. * mu * theta_bar;
      return result;
    }



    template <int dim>
    double
    J2Plasticity<dim>::return_step(const double norm,
                                   const double alpha_before,
                                   const double mu) const
    {
      // g(s) = norm - (2 mu + 2/3 H_kin) s - sqrt(2/3) sigma_y(alpha + sqrt(2/3) s)
      // falls from g(0) > 0 (beyond the yield surface) to g(norm / c) < 0:
      // Newton's method kept inside that bracket (bisection where a step
      // leaves it). Linear hardening: the first step is the exact one.
      const double c     = 2. * mu + 2. / 3. * kinematic_hardening;
      const double root  = std::sqrt(2. / 3.);
      const auto   g     = [&](const double s) {
        return norm - c * s - root * hardening.yield_stress(alpha_before + root * s);
      };
      double low = 0, high = norm / c;
      double s = (norm - root * hardening.yield_stress(alpha_before)) /
                 (c + 2. / 3. * hardening.slope(alpha_before));
      for (unsigned int k = 0; k < 100; ++k)
        {
          const double value = g(s);
          if (std::abs(value) <= 1e-14 * norm)
            break;
          (value > 0 ? low : high) = s;
          const double next =
            s + value / (c + 2. / 3. * hardening.slope(alpha_before + root * s));
          s = (next > low && next < high) ? next : 0.5 * (low + high);
        }
      return s;
    }



    template <int dim>
    void
    J2Plasticity<dim>::tangent_of_strain(const double                 kappa,
                                         const double                 mu,
                                         const double                 flow,
                                         const SymmetricTensor<2, 3> &n,
                                         MaterialResponse<dim>       &response) const
    {
      // D = kappa I (x) I + 2 mu P_dev + flow n (x) n on the 3D strain, then
      // the chain rule through dev(embed(epsilon)) + theta/3 I: with
      // D_t = D : I / 3 (the part of the volumetric strain),
      // d sigma/d epsilon = D - D_t (x) I, d sigma/d theta = D_t,
      // d pi/d epsilon = (I : D - 3 I : D_t I) / 3 on the deviator,
      // d pi/d theta = I : D_t / 3.
      double D[3][3][3][3];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              D[i][j][k][l] = (i == j && k == l ? kappa - 2. * mu / 3. : 0.) +
                              mu * ((i == k && j == l ? 1. : 0.) +
                                    (i == l && j == k ? 1. : 0.)) +
                              flow * n[i][j] * n[k][l];
      double D_trace[3][3], trace_D[3][3], trace_D_trace = 0;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            D_trace[i][j] = D[i][j][0][0] + D[i][j][1][1] + D[i][j][2][2];
            trace_D[i][j] = D[0][0][i][j] + D[1][1][i][j] + D[2][2][i][j];
          }
      for (unsigned int i = 0; i < 3; ++i)
        trace_D_trace += D_trace[i][i];
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                response.stress_by_strain[i][j][k][l] =
                  D[i][j][k][l] - (k == l ? D_trace[i][j] / 3. : 0.);
            if (j >= i)
              {
                response.stress_by_volumetric_strain[i][j] = D_trace[i][j] / 3.;
                response.volumetric_stress_by_strain[i][j] =
                  (trace_D[i][j] - (i == j ? trace_D_trace / 3. : 0.)) / 3.;
              }
          }
      response.volumetric_stress_by_volumetric_strain = trace_D_trace / 9.;
    }



    template <int dim>
    SymmetricTensor<2, 3>
    J2Plasticity<dim>::plastic_strain(const double *history) const
    {
      if (!this->elastic().finite_strain)
        return read_history_tensor(history);
      // ln(Cp) / 2 = -ln(Cp^-1) / 2.
      const SpectralDecomposition inverse_plastic(unit_symmetric_tensor<3>() +
                                                  read_history_tensor(history));
      return inverse_plastic.map([](const double x) { return -0.5 * std::log(x); });
    }



    template <int dim>
    typename MaterialModel<dim>::VolumeRatio
    J2Plasticity<dim>::volume_ratio() const
    {
      using VolumeRatio = typename MaterialModel<dim>::VolumeRatio;
      if (!this->elastic().finite_strain)
        return VolumeRatio::none;
      return this->elastic().mean_volume_ratio ? VolumeRatio::cell_mean : VolumeRatio::point;
    }



    template <int dim>
    std::string
    J2Plasticity<dim>::describe() const
    {
      return "J2 plasticity (yield stress " + Input::to_text(hardening.yield_stress(0)) +
             ", hardening " + hardening.describe() + " isotropic, " +
             Input::to_text(kinematic_hardening) + " kinematic" +
             (this->elastic().finite_strain ?
                std::string(this->elastic().mean_volume_ratio ?
                              "; Hencky, exponential map, mean dilatation" :
                              "; Hencky, exponential map") :
                std::string()) +
             "), " + this->elastic().describe();
    }

    FRICTIONAL_CONTACT_REGISTER_PLUGIN(
      MaterialModel,
      J2Plasticity,
      "J2 plasticity",
      "Von Mises plasticity with isotropic hardening (linear, Voce or a "
      "measured flow curve) and, at small strain, linear kinematic hardening "
      "(radial return, consistent tangent). At finite strain (<Material/"
      "Kinematics>) F = Fe Fp with the Hencky elastic law and the exponential "
      "map; its entries in Material/J2 plasticity.")
  } // namespace MaterialLaws
} // namespace FrictionalContact
