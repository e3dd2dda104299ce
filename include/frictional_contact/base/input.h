#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * An error in what the user gave us (parameter file, mesh file, command
   * line). main() prints its message as one line, without a stack trace,
   * and exits with a non-zero code.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A solve that failed (no convergence, NaN, breakdown). Reported like an
   * InputError, after the solver has printed its residuals.
   */
  class SolverError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A displacement that inverts a cell of a finite-strain body (det F <=
   * 0 at a point): no state of the law. Newton's line search shortens a
   * step that meets it; elsewhere it stops the solve like any SolverError.
   */
  class InvertedCell : public SolverError
  {
  public:
    using SolverError::SolverError;
  };

  /**
   * An entry of the input that evaluates to NaN or infinity at a time the
   * loading history reaches (a load factor 1/(t - 1) at t = 1). Stops the
   * run with exit code 2 like a SolverError, but is never retried with a
   * smaller increment: it is not the solver's to fix.
   */
  class NonFiniteInput : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A write that failed: no space left, a quota reached, another I/O
   * error. Its message names the file and the cause. main() prints it as
   * one line and exits with code 74 (EX_IOERR); everything written before
   * stays complete (each file is written to a temporary and renamed).
   */
  class WriteError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  namespace Input
  {
    /// Splits @p text at @p separator and trims each piece; empty pieces are dropped.
    std::vector<std::string>
    split(const std::string &text, const char separator);

    std::string
    trim(const std::string &text);

    /// A number as a user would write it: 6 significant digits, no padding.
    std::string
    to_text(const double value);

    /// A number in scientific notation with @p digits decimals ("1.234e-05").
    std::string
    scientific(const double value, const unsigned int digits = 3);

    /// Parses "a, b[, c]" with exactly dim numbers; the error names @p entry.
    template <int dim>
    Tensor<1, dim>
    parse_vector(const std::string &entry, const std::string &text);

    /// The finite number that is the whole of @p text; else fail(@p entry,
    /// @p text, @p allowed).
    double
    parse_number(const std::string &entry,
                 const std::string &text,
                 const std::string &allowed);

    /// @p text as one line: white space folded, bytes that are not
    /// printable ASCII shown as '?', at most @p max_length characters.
    std::string
    one_line(const std::string &text, const std::size_t max_length = 400);

    /// Throws a NonFiniteInput naming @p entry and @p t unless @p value is finite.
    void
    require_finite(const double value, const std::string &entry, const double t);

    /// Throws an InputError naming the entry, its value and what is allowed.
    [[noreturn]] void
    fail(const std::string &entry,
         const std::string &value,
         const std::string &allowed);
  } // namespace Input

  /**
   * Symbolic boundary names of a geometry (such as "left" or "bottom") and
   * the boundary ids the mesh really has. Turns what a user writes in a
   * parameter file (a name or a number) into a boundary id.
   */
  class BoundaryNames
  {
  public:
    BoundaryNames() = default;
    BoundaryNames(std::map<std::string, types::boundary_id> names,
                  std::set<types::boundary_id>              ids_in_mesh);

    /// The id for a name or number; the error names @p entry and the choices.
    types::boundary_id
    id(const std::string &entry, const std::string &name_or_number) const;

    /// The name of @p id, or its number as text if it has none.
    std::string
    name(const types::boundary_id id) const;

    /// "left (0), right (1), ..." for error messages.
    std::string
    describe() const;

  private:
    std::map<std::string, types::boundary_id> names;
    std::set<types::boundary_id>              ids_in_mesh;
  };
} // namespace FrictionalContact
