#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * The entries of the subsection "Material" (or of one of its subsections)
   * as one body sees them: an entry holds one value for every body, or
   * 'body: value; other body: value'. Names each entry in its errors with
   * its full path, and refuses a value for a body the geometry does not
   * have.
   */
  class BodyEntries
  {
  public:
    /// The entries of the subsection @p subsections (from the top level:
    /// {"Material"}, {"Material", "J2 plasticity"}) of @p prm, which must
    /// be at its top level when they are read, for the body @p body of the
    /// bodies @p all_bodies.
    BodyEntries(const ParameterHandler         &prm,
                const std::vector<std::string> &subsections,
                const std::string              &body,
                const std::vector<std::string> &all_bodies);

    /// The value of @p entry for this body.
    std::string
    get(const std::string &entry) const;

    /// The value of @p entry as a finite number.
    double
    get_number(const std::string &entry) const;

    /// The full name of @p entry, for messages ("Material/Yield stress").
    std::string
    path_of(const std::string &entry) const
    {
      return path + "/" + entry;
    }

    const std::string &
    body() const
    {
      return body_name;
    }

  private:
    const ParameterHandler         &prm;
    const std::vector<std::string>  subsections;
    const std::string               path;
    const std::string               body_name;
    const std::vector<std::string> &all_bodies;
  };



  /**
   * Isotropic elastic constants of a body: Young's modulus, Poisson's
   * ratio, in 2D plane stress or plane strain, and the element formulation
   * that carries the volumetric strain (the standard Q1 element, or the
   * mean-dilatation B-bar element that does not lock as nu approaches 1/2,
   * or where plastic flow is isochoric), and the kinematics (small strain,
   * or finite strain: total Lagrangian). Owns the stress-strain tensor of
   * linear elasticity and its split into shear and bulk parts.
   */
  template <int dim>
  class ElasticConstants
  {
  public:
    /// Declares the entries of the subsection "Material" that every law
    /// reads.
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Reads the elastic entries of "Material" for one body. @p isochoric:
     * whether the body's law flows without changing volume (plasticity),
     * so that Formulation = auto takes the B-bar element for it.
     */
    ElasticConstants(const BodyEntries &entries, const bool isochoric);

    /// The fourth-order tensor C with sigma = C : epsilon (of the standard
    /// element).
    const SymmetricTensor<4, dim> &
    stress_strain_tensor() const
    {
      return stiffness;
    }

    /**
     * The stress of a strain @p strain whose volumetric part (its trace)
     * is replaced by @p volumetric_strain: the cell average of the trace
     * for the B-bar element, the trace itself for the standard one.
     * sigma = 2 G dev(epsilon) + K theta I, with the deviator and the
     * bulk modulus K of dim dimensions (the in-plane ones in 2D).
     */
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain,
           const double                   volumetric_strain) const;

    /// The out-of-plane normal stress of plane strain (zero in plane
    /// stress) for the in-plane stress @p stress.
    double
    out_of_plane_stress(const SymmetricTensor<2, dim> &stress) const;

    /// The mean stress trace(sigma)/3 (of the 3D stress, in 2D with the
    /// out-of-plane stress) for a volumetric strain @p volumetric_strain.
    double
    mean_stress(const double volumetric_strain) const;

    /// "E = 1, nu = 0.3, plane stress" (and ", B-bar element" when used)
    std::string
    describe() const;

    /**
     * A warning line when the standard element is forced on a nearly
     * incompressible material (it locks); empty otherwise.
     */
    std::string
    locking_warning() const;

    double youngs_modulus;
    double poissons_ratio;
    bool   plane_stress;
    /// Whether <Material/Two-dimensional model> = axisymmetric: the body
    /// is a 2D section (x = r, y the axis) of a body of revolution. Its
    /// 3D law (Materials::revolved()) has it too.
    bool   axisymmetric;
    /// Whether the mean-dilatation (B-bar) element is used.
    bool   mean_dilatation;
    /// At finite strain, whether a law that flows isochorically takes the
    /// cell's mean volume ratio (the mean-dilatation element of Simo,
    /// Taylor and Pister; Formulation = auto) rather than the point's.
    bool   mean_volume_ratio;
    /// Whether the body is at finite strain (<Material/Kinematics>): the
    /// law's strain is then the Green-Lagrange strain E and its stress the
    /// second Piola-Kirchhoff stress S.
    bool   finite_strain;
    /// Whether the law is evaluated at the 3 x 3 (x 3) Gauss-Lobatto
    /// points, the cell's corners among them (<Material/Quadrature>;
    /// finite strain only), instead of the 2 x 2 (x 2) Gauss points.
    bool   corner_points;
    /// G: the shear modulus.
    double shear_modulus;
    /// K: the bulk modulus of dim-dimensional elasticity (lambda + 2 G / dim,
    /// with the plane-stress lambda in 2D plane stress).
    double bulk_modulus;
    /// The bulk modulus of 3D elasticity, lambda + 2 G / 3 (kappa).
    double bulk_modulus_3d;

    /// Above this Poisson's ratio, 'auto' picks the B-bar element.
    static constexpr double locking_threshold = 0.45;

  private:
    SymmetricTensor<4, dim> stiffness;
    /// Whether the user forced the standard element.
    bool standard_forced;
    /// Whether auto chose the B-bar element for an isochoric flow.
    bool mean_dilatation_for_flow;
  };



  /**
   * What a material law gives at a quadrature point: the in-plane stress
   * sigma (dim x dim), the stress conjugate to the volumetric strain of the
   * element (pi: the mean stress, or for linear elasticity K theta), the
   * out-of-plane normal stress in 2D, and, if asked, their derivatives with
   * respect to the strain and the volumetric strain. With theta the trace
   * of the strain (standard element) the stiffness is d sigma/d epsilon +
   * d sigma/d theta (x) I; with theta its cell average (B-bar) the element
   * assembles all four (SolidBody).
   */
  template <int dim>
  struct MaterialResponse
  {
    SymmetricTensor<2, dim> stress;
    double                  volumetric_stress   = 0;
    double                  out_of_plane_stress = 0;
    /// All dim^4 components (with the minor symmetries): the element reads
    /// them by index, which a SymmetricTensor makes slow.
    Tensor<4, dim>          stress_by_strain;
    SymmetricTensor<2, dim> stress_by_volumetric_strain;
    SymmetricTensor<2, dim> volumetric_stress_by_strain;
    double                  volumetric_stress_by_volumetric_strain = 0;
    /// Whether the point flows plastically in this step, and whether it
    /// is on the yield surface (also once its flow is committed).
    bool plastic  = false;
    bool at_yield = false;
  };



  /**
   * A material law: the stress at a quadrature point for a strain and the
   * element's volumetric strain, given the point's committed history (its
   * internal variables after the last accepted increment), and the history
   * that goes with the new strain, which the body commits only when an
   * increment is accepted. Laws are plugins registered by name
   * (FRICTIONAL_CONTACT_REGISTER_PLUGIN(MaterialModel, ...)), chosen per
   * body by <Material/Model>; each reads the elastic entries of "Material"
   * and its own subsection "Material/<name>". ASPECT's MaterialModel and
   * step-42's ConstitutiveLaw are the models.
   */
  template <int dim>
  class MaterialModel
  {
  public:
    virtual ~MaterialModel() = default;

    /// Reads the law's entries for one body (the base class reads the
    /// elastic ones; call it first).
    virtual void
    parse_parameters(const BodyEntries &material, const BodyEntries &own);

    /// Whether the stress is linear in the strain without history: the
    /// body then assembles K once, and the solvers take it as it is.
    virtual bool
    is_linear() const = 0;

    /// Whether inelastic flow keeps the volume (Formulation = auto then
    /// takes the B-bar element).
    virtual bool
    flows_isochorically() const
    {
      return false;
    }

    /// Whether the law is written for finite strain too (a stress S of the
    /// Green-Lagrange strain E), and whether it is for finite strain only
    /// (it means nothing at small strain).
    virtual bool
    allows_finite_strain() const
    {
      return false;
    }
    virtual bool
    needs_finite_strain() const
    {
      return false;
    }

    /**
     * Whether the law's volumetric strain is a volume ratio theta (finite
     * strain), and which: the cell's mean of det F (a mean-dilatation
     * element) or the point's det F (the standard element). The body then
     * passes theta to evaluate(), and the law gives dS/dtheta as
     * stress_by_volumetric_strain, which the body couples through d theta /
     * du over the cell or at the point. 'none': the volumetric strain of
     * the small-strain element.
     */
    enum class VolumeRatio
    {
      none,
      cell_mean,
      point
    };
    virtual VolumeRatio
    volume_ratio() const
    {
      return VolumeRatio::none;
    }

    /// How many history values a quadrature point keeps (0: none).
    virtual unsigned int
    n_history_values() const
    {
      return 0;
    }

    /**
     * The response at a point of strain @p strain and volumetric strain
     * @p volumetric_strain from the committed history @p history (of
     * n_history_values(); nullptr for none), with the derivatives if
     * @p with_tangent; the history that goes with it into @p new_history
     * (if not nullptr).
     */
    virtual void
    evaluate(const SymmetricTensor<2, dim> &strain,
             const double                   volumetric_strain,
             const double                  *history,
             const bool                     with_tangent,
             MaterialResponse<dim>         &response,
             double                        *new_history) const = 0;

    /// The equivalent plastic strain of a history (0 without).
    virtual double
    equivalent_plastic_strain(const double * /*history*/) const
    {
      return 0;
    }

    /// The plastic strain tensor of a history (3D; zero without).
    virtual SymmetricTensor<2, 3>
    plastic_strain(const double * /*history*/) const
    {
      return {};
    }

    /// "E = 1, nu = 0.3" and what the law adds ("J2, yield stress 400").
    virtual std::string
    describe() const;

    const ElasticConstants<dim> &
    elastic() const
    {
      return *elastic_constants;
    }

  protected:
    std::unique_ptr<ElasticConstants<dim>> elastic_constants;
  };



  /**
   * A hyperelastic law of finite strain without history (the neo-Hookean
   * laws): not linear, and for finite strain only (it means nothing at
   * small strain).
   */
  template <int dim>
  class HyperelasticLaw : public MaterialModel<dim>
  {
  public:
    bool
    is_linear() const override
    {
      return false;
    }

    bool
    allows_finite_strain() const override
    {
      return true;
    }

    bool
    needs_finite_strain() const override
    {
      return true;
    }

  protected:
    /// The entries of @p t as a plain array, for the tangent's loops: a
    /// SymmetricTensor finds each entry by index arithmetic at each access.
    static void
    plain_copy(const SymmetricTensor<2, dim> &t, double (&entries)[dim][dim])
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          entries[i][j] = t[i][j];
    }
  };



  /**
   * The material of each body of the scene (bodies are the material ids of
   * the mesh, named by the geometry), read from the subsection "Material":
   * <Material/Model> names each body's law. Owns one law per body.
   */
  template <int dim>
  class Materials
  {
  public:
    /// Declares <Material/Model>, the elastic entries and every law's own
    /// subsection.
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads the subsection "Material" for the bodies @p bodies (name ->
    /// material id).
    Materials(ParameterHandler                                &prm,
              const std::map<std::string, types::material_id> &bodies);

    /// The law of the cells with material id @p id.
    const MaterialModel<dim> &
    of(const types::material_id id) const;

    /// Whether the scene is axisymmetric (<Material/Two-dimensional model>
    /// = axisymmetric for every body).
    bool
    axisymmetric() const
    {
      return !revolved_laws.empty();
    }

    /// The 3D law of the body of material id @p id of an axisymmetric
    /// scene: it gives the stress of a strain with the hoop component.
    const MaterialModel<3> &
    revolved(const types::material_id id) const;

    /// How many history values a point of the body @p id keeps (of its
    /// 3D law in an axisymmetric scene).
    unsigned int
    history_size(const types::material_id id) const
    {
      return axisymmetric() ? revolved(id).n_history_values() : of(id).n_history_values();
    }

    /// Whether some body uses the B-bar element.
    bool
    any_mean_dilatation() const;

    /// Whether every body is linear elastic at small strain.
    bool
    all_linear() const;

    /// Whether some body is at finite strain.
    bool
    any_finite_strain() const;

    /// What makes the bodies nonlinear, as the entries that say so: for
    /// example "<Material/Model> = J2 plasticity" or "<Material/Kinematics>
    /// = finite strain" (empty when all_linear()).
    std::string
    describe_nonlinearity() const;

    /// The largest Young's modulus of the bodies over the smallest.
    double
    largest_modulus_ratio() const;

    /// The largest number of history values of any body's law.
    unsigned int
    max_history_values() const;

    /// "E = 1, nu = 0.3" for one body, "base: E = ...; block: ..." for more.
    std::string
    describe() const;

    /// The locking warnings of the bodies, one line each.
    std::vector<std::string>
    locking_warnings() const;

  private:
    std::map<types::material_id, std::unique_ptr<MaterialModel<dim>>> materials;
    std::map<types::material_id, std::string>                         names;
    /// Each body's <Material/Model>.
    std::map<types::material_id, std::string> law_names;
    /// Of an axisymmetric scene (2D): each body's law in 3D.
    std::map<types::material_id, std::unique_ptr<MaterialModel<3>>> revolved_laws;
  };
} // namespace FrictionalContact
