// The exchange with FCLIB files (through libfclib) and FCLIB's error measure.
#include <frictional_contact/base/files.h>
#include <frictional_contact/fclib/fclib_problem.h>
#include <frictional_contact/solvers/friction_cone.h>
#include <frictional_contact/base/input.h>

extern "C"
{
#include <fclib.h>
}
#include <hdf5.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>

namespace FrictionalContact
{
  namespace
  {
    /**
     * Sends the standard error stream to /dev/null while it lives: libfclib
     * and HDF5 print diagnostics there for every optional field a file does
     * not have; we report problems ourselves.
     */
    class QuietStandardError
    {
    public:
      QuietStandardError()
        : saved(dup(STDERR_FILENO))
      {
        std::fflush(stderr);
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0)
          {
            dup2(null, STDERR_FILENO);
            close(null);
          }
      }

      ~QuietStandardError()
      {
        std::fflush(stderr);
        if (saved >= 0)
          {
            dup2(saved, STDERR_FILENO);
            close(saved);
          }
      }

    private:
      int saved;
    };

    double
    norm(const std::vector<double> &x)
    {
      double sum = 0;
      for (const double x_i : x)
        sum += x_i * x_i;
      return std::sqrt(sum);
    }

    [[noreturn]] void
    fail(const std::string &path, const std::string &what)
    {
      throw InputError("the FCLIB file '" + path + "' " + what);
    }

    /**
     * Whether @p path is an HDF5 file with the group (or data set) @p group,
     * a path whose every parent must exist. libfclib's
     * readers must only be called then: fclib_read_solution() ends the
     * process when the file has no solution.
     */
    bool
    has_group(const std::string &path, const std::string &group)
    {
      QuietStandardError quiet;
      if (H5Fis_hdf5(path.c_str()) <= 0)
        return false;
      const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      if (file < 0)
        return false;
      const bool found = H5Lexists(file, group.c_str(), H5P_DEFAULT) > 0;
      H5Fclose(file);
      return found;
    }

    /// The entries of @p matrix, whatever its storage (triplets, CSC, CSR).
    std::vector<MatrixEntry>
    entries_of(const fclib_matrix *matrix,
               const std::string  &path,
               const std::string  &name)
    {
      if (matrix == nullptr)
        fail(path, "has no matrix " + name);
      std::vector<MatrixEntry> entries;
      const auto add = [&](const int row, const int column, const double value) {
        if (row < 0 || row >= matrix->m || column < 0 || column >= matrix->n)
          fail(path, "has an entry of " + name + " outside its " +
                       std::to_string(matrix->m) + " x " +
                       std::to_string(matrix->n) + " size");
        if (!std::isfinite(value))
          fail(path, "has a NaN or infinite entry in " + name);
        entries.push_back({static_cast<unsigned int>(row),
                           static_cast<unsigned int>(column),
                           value});
      };
      if (matrix->nz >= 0) // triplets: i rows, p columns (CSparse)
        for (int k = 0; k < matrix->nz; ++k)
          add(matrix->i[k], matrix->p[k], matrix->x[k]);
      else if (matrix->nz == -1) // compressed columns
        for (int column = 0; column < matrix->n; ++column)
          for (int k = matrix->p[column]; k < matrix->p[column + 1]; ++k)
            add(matrix->i[k], column, matrix->x[k]);
      else if (matrix->nz == -2) // compressed rows
        for (int row = 0; row < matrix->m; ++row)
          for (int k = matrix->p[row]; k < matrix->p[row + 1]; ++k)
            add(row, matrix->i[k], matrix->x[k]);
      else
        fail(path, "stores " + name + " in an unknown format (nz = " +
                     std::to_string(matrix->nz) + ")");
      return entries;
    }

    std::vector<double>
    copy_of(const double      *values,
            const unsigned int size,
            const std::string &path,
            const std::string &name)
    {
      if (values == nullptr)
        fail(path, "has no vector " + name);
      std::vector<double> copy(values, values + size);
      for (const double value : copy)
        if (!std::isfinite(value))
          fail(path, "has a NaN or infinite entry in " + name);
      return copy;
    }


    /// A libfclib matrix (triplets) viewing @p entries.
    struct MatrixView
    {
      MatrixView(const std::vector<MatrixEntry> &entries,
                 const unsigned int              m,
                 const unsigned int              n)
      {
        for (const auto &e : entries)
          {
            rows.push_back(e.row);
            columns.push_back(e.column);
            values.push_back(e.value);
          }
        matrix.nzmax = entries.size();
        matrix.m     = m;
        matrix.n     = n;
        matrix.p     = columns.data();
        matrix.i     = rows.data();
        matrix.x     = values.data();
        matrix.nz    = entries.size();
        matrix.info  = nullptr;
      }

      std::vector<int>    rows;
      std::vector<int>    columns;
      std::vector<double> values;
      fclib_matrix        matrix;
    };

    /// P_K: the projection onto FCLIB's cone {|r_t| <= mu r_n}, which is
    /// FrictionCone's (Algorithm 3) with the sign of the normal flipped.
    template <int dim>
    void
    project_onto_cone(double *r, const double mu)
    {
      Tensor<1, dim> s;
      for (unsigned int k = 0; k < dim; ++k)
        s[k] = r[k];
      s[0] = -s[0];
      const Tensor<1, dim> projection = FrictionCone<dim>(mu).project(s);
      for (unsigned int k = 0; k < dim; ++k)
        r[k] = projection[k];
      r[0] = -r[0];
    }
  } // namespace



  double
  asymmetry(const std::vector<MatrixEntry> &A)
  {
    // The entries row by row (a counting sort), each row sorted by column
    // with repeated entries summed: one global sort of the entries took as
    // long as the whole Newton solve of a file of 675 unknowns.
    unsigned int n = 0;
    for (const auto &e : A)
      n = std::max({n, e.row + 1, e.column + 1});
    std::vector<std::size_t> row_start(n + 1, 0);
    for (const auto &e : A)
      ++row_start[e.row + 1];
    for (unsigned int i = 0; i < n; ++i)
      row_start[i + 1] += row_start[i];
    std::vector<std::pair<unsigned int, double>> entries(A.size());
    std::vector<std::size_t> next(row_start.begin(), row_start.end() - 1);
    for (const auto &e : A)
      entries[next[e.row]++] = {e.column, e.value};
    std::vector<std::size_t> row_end(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto first = entries.begin() + row_start[i];
        const auto last  = entries.begin() + row_start[i + 1];
        std::sort(first, last, [](const auto &a, const auto &b) {
          return a.first < b.first;
        });
        auto end = first;
        for (auto k = first; k != last; ++k)
          if (end != first && (end - 1)->first == k->first)
            (end - 1)->second += k->second;
          else
            *end++ = *k;
        row_end[i] = end - entries.begin();
      }
    const auto value_at = [&](const unsigned int i, const unsigned int j) {
      const auto first = entries.begin() + row_start[i];
      const auto last  = entries.begin() + row_end[i];
      const auto entry = std::lower_bound(
        first, last, j, [](const auto &a, const unsigned int c) { return a.first < c; });
      return entry != last && entry->first == j ? entry->second : 0.;
    };

    double largest = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (std::size_t k = row_start[i]; k < row_end[i]; ++k)
        {
          const auto [j, value] = entries[k];
          const double other    = value_at(j, i);
          if (value == other)
            continue;
          const double scale = std::sqrt(std::abs(value_at(i, i) * value_at(j, j)));
          largest = std::max(largest,
                             scale > 0 ? std::abs(value - other) / scale :
                                         std::numeric_limits<double>::infinity());
        }
    return largest;
  }



  FclibProblem
  read_fclib_problem(const std::string &path)
  {
    if (access(path.c_str(), R_OK) != 0)
      throw InputError("cannot open the FCLIB file '" + path +
                       "': check the path");
    if (!has_group(path, "fclib_global"))
      fail(path, "has no global problem (an HDF5 file with the group "
                 "fclib_global is expected)");
    // libfclib's reader ends the process on a group that lacks one of these.
    for (const std::string member : {"spacedim", "M", "H", "vectors"})
      if (!has_group(path, "fclib_global/" + member))
        fail(path, "has an incomplete global problem: fclib_global/" + member +
                     " is missing (an FCLIB global problem has M, H, "
                     "vectors and spacedim)");
    std::unique_ptr<fclib_global, void (*)(fclib_global *)> global(
      nullptr, fclib_delete_global);
    {
      QuietStandardError quiet;
      global.reset(fclib_read_global(path.c_str()));
    }
    if (!global)
      fail(path, "has no global problem (group fclib_global) that libfclib "
                 "can read");
    if (global->spacedim != 2 && global->spacedim != 3)
      fail(path, "has spacedim " + std::to_string(global->spacedim) +
                   "; 2 or 3 is expected");
    if (global->G != nullptr && global->G->n > 0)
      fail(path, "has equality constraints (G, b); only problems without "
                 "them can be solved here");

    FclibProblem problem;
    problem.spacedim = global->spacedim;
    if (global->M == nullptr || global->H == nullptr)
      fail(path, "has no matrix M or H");
    problem.n = global->M->n;
    if (global->M->m != global->M->n)
      fail(path, "has a non-square M (" + std::to_string(global->M->m) +
                   " x " + std::to_string(global->M->n) + ")");
    if (global->H->m != global->M->n || global->H->n % global->spacedim != 0 ||
        global->H->n == 0)
      fail(path, "has H of size " + std::to_string(global->H->m) + " x " +
                   std::to_string(global->H->n) + "; " +
                   std::to_string(problem.n) + " x (" +
                   std::to_string(global->spacedim) +
                   " x number of contacts) is expected");
    const unsigned int m = global->H->n;
    problem.M  = entries_of(global->M, path, "M");
    problem.H  = entries_of(global->H, path, "H");
    problem.f  = copy_of(global->f, problem.n, path, "f");
    problem.w  = copy_of(global->w, m, path, "w");
    problem.mu = copy_of(global->mu, m / problem.spacedim, path, "mu");
    for (const double mu : problem.mu)
      if (mu != problem.mu[0] || !(mu >= 0))
        fail(path, "has friction coefficients from " +
                     Input::to_text(*std::min_element(problem.mu.begin(),
                                                      problem.mu.end())) +
                     " to " +
                     Input::to_text(*std::max_element(problem.mu.begin(),
                                                      problem.mu.end())) +
                     "; one coefficient >= 0 for all contacts is expected");
    if (global->info != nullptr)
      {
        if (global->info->title != nullptr)
          problem.title = global->info->title;
        if (global->info->description != nullptr)
          problem.description = global->info->description;
      }
    return problem;
  }



  FclibSolution
  read_fclib_solution(const std::string &path, const FclibProblem &problem)
  {
    if (access(path.c_str(), R_OK) != 0)
      throw InputError("cannot open the FCLIB file '" + path +
                       "': check the path");
    if (!has_group(path, "solution"))
      fail(path, "has no solution (group solution with v and r)");
    fclib_solution *stored = nullptr;
    {
      QuietStandardError quiet;
      stored = fclib_read_solution(path.c_str());
    }
    if (stored == nullptr || stored->v == nullptr || stored->r == nullptr)
      {
        if (stored != nullptr)
          fclib_delete_solutions(stored, 1);
        fail(path, "has no solution (group solution with v and r)");
      }
    const unsigned int m = problem.w.size();
    FclibSolution      solution;
    solution.v = std::vector<double>(stored->v, stored->v + problem.n);
    solution.r = std::vector<double>(stored->r, stored->r + m);
    fclib_delete_solutions(stored, 1);
    solution.u = local_velocity(problem, solution.v);
    return solution;
  }



  void
  write_fclib(const std::string   &path,
              const FclibProblem  &problem,
              const FclibSolution *solution)
  {
    const unsigned int m = problem.w.size();
    MatrixView         M(problem.M, problem.n, problem.n);
    MatrixView         H(problem.H, problem.n, m);
    std::vector<double> f = problem.f, w = problem.w, mu = problem.mu;
    std::string title = problem.title, description = problem.description,
                math_info = "M symmetric positive definite";
    fclib_info info{title.data(), description.data(), math_info.data()};
    fclib_global global{};
    global.M        = &M.matrix;
    global.H        = &H.matrix;
    global.G        = nullptr;
    global.mu       = mu.data();
    global.f        = f.data();
    global.b        = nullptr;
    global.w        = w.data();
    global.spacedim = problem.spacedim;
    global.info     = &info;

    const std::string temporary = path + ".part";
    std::remove(temporary.c_str());
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::error_code             ignored;
    if (!folder.empty())
      std::filesystem::create_directories(folder, ignored);
    bool written = false;
    {
      QuietStandardError quiet;
      written = fclib_write_global(&global, temporary.c_str()) == 1;
      if (written && solution != nullptr)
        {
          FclibSolution  copy = *solution;
          fclib_solution stored{copy.v.data(),
                                copy.u.data(),
                                copy.r.data(),
                                nullptr};
          written = fclib_write_solution(&stored, temporary.c_str()) == 1;
        }
    }
    if (!written || std::rename(temporary.c_str(), path.c_str()) != 0)
      {
        std::remove(temporary.c_str());
        // HDF5 does not say why; a reservation in the same folder does.
        const std::string space = space_problem(folder.string(), 1 << 20);
        if (!space.empty())
          throw WriteError("cannot write the FCLIB file '" + path + "': " + space);
        throw InputError("cannot write the FCLIB file '" + path +
                         "': check that its folder exists and is writable");
      }
  }



  std::vector<double>
  local_velocity(const FclibProblem &problem, const std::vector<double> &v)
  {
    std::vector<double> u = problem.w;
    for (const auto &e : problem.H)
      u[e.column] += e.value * v[e.row];
    return u;
  }



  double
  fclib_error(const FclibProblem &problem, const FclibSolution &solution)
  {
    // A part is divided by its scale only where that is above the machine
    // epsilon (a zero problem has an absolute error).
    const auto relative = [](const double value, const double scale) {
      return scale > std::numeric_limits<double>::epsilon() ? value / scale :
                                                              value;
    };

    // Equilibrium: |f + H r - M v| / max(|f|, |M v|, |H r|).
    std::vector<double> M_v(problem.n, 0.), H_r(problem.n, 0.);
    for (const auto &e : problem.M)
      M_v[e.row] += e.value * solution.v[e.column];
    for (const auto &e : problem.H)
      H_r[e.row] += e.value * solution.r[e.column];
    std::vector<double> imbalance = problem.f;
    for (unsigned int i = 0; i < problem.n; ++i)
      imbalance[i] += H_r[i] - M_v[i];
    const double equilibrium =
      relative(norm(imbalance),
               std::max({norm(problem.f), norm(M_v), norm(H_r)}));

    // The natural map of each contact, with De Saxce's modified velocity:
    // |r - P_K(r - u_hat)| / max(|u|, |r|).
    const std::vector<double> u = local_velocity(problem, solution.v);
    const unsigned int        d = problem.spacedim;
    double                    sum = 0;
    for (unsigned int c = 0; c < problem.n_contacts(); ++c)
      {
        const double *r_c = &solution.r[d * c];
        const double *u_c = &u[d * c];
        double        u_t = 0;
        for (unsigned int k = 1; k < d; ++k)
          u_t += u_c[k] * u_c[k];
        double s[3];
        for (unsigned int k = 0; k < d; ++k)
          s[k] = r_c[k] - u_c[k];
        s[0] -= problem.mu[c] * std::sqrt(u_t);
        if (d == 2)
          project_onto_cone<2>(s, problem.mu[c]);
        else
          project_onto_cone<3>(s, problem.mu[c]);
        for (unsigned int k = 0; k < d; ++k)
          sum += std::pow(r_c[k] - s[k], 2);
      }
    const double complementarity =
      relative(std::sqrt(sum), std::max(norm(u), norm(solution.r)));
    return equilibrium + complementarity;
  }



  double
  relative_difference(const std::vector<double> &x, const std::vector<double> &y)
  {
    std::vector<double> difference = x;
    for (unsigned int i = 0; i < x.size(); ++i)
      difference[i] -= y[i];
    const double reference = norm(y);
    return reference > 0 ? norm(difference) / reference : norm(difference);
  }
} // namespace FrictionalContact
