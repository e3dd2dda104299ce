#include <frictional_contact/material/spectral_decomposition.h>

namespace FrictionalContact
{
  SpectralDecomposition::SpectralDecomposition(const SymmetricTensor<2, 3> &X)
  {
    const auto pairs = eigenvectors(X, SymmetricTensorEigenvectorMethod::ql_implicit_shifts);
    for (unsigned int a = 0; a < 3; ++a)
      {
        values[a] = pairs[a].first;
        for (unsigned int i = 0; i < 3; ++i)
          vectors[i][a] = pairs[a].second[i];
      }
  }



  SymmetricTensor<2, 3>
  SpectralDecomposition::to_eigenbasis(const SymmetricTensor<2, 3> &T) const
  {
    return symmetrize(transpose(vectors) * Tensor<2, 3>(T) * vectors);
  }



  SymmetricTensor<2, 3>
  SpectralDecomposition::from_eigenbasis(const SymmetricTensor<2, 3> &T) const
  {
    return symmetrize(vectors * Tensor<2, 3>(T) * transpose(vectors));
  }



  SymmetricTensor<2, 3>
  SpectralDecomposition::from_eigenbasis_diagonal(const std::array<double, 3> &d) const
  {
    // By the raw entries (00, 11, 22, 01, 02, 12): the accessors of
    // result[i][j] cost more than the sum.
    static constexpr unsigned int row[6] = {0, 1, 2, 0, 0, 1}, column[6] = {0, 1, 2, 1, 2, 2};
    SymmetricTensor<2, 3>         result;
    for (unsigned int k = 0; k < 6; ++k)
      {
        double sum = 0;
        for (unsigned int a = 0; a < 3; ++a)
          sum += d[a] * vectors[row[k]][a] * vectors[column[k]][a];
        result.access_raw_entry(k) = sum;
      }
    return result;
  }



  SymmetricTensor<2, 3>
  congruence(const SymmetricTensor<2, 3> &F, const SymmetricTensor<2, 3> &T)
  {
    const Tensor<2, 3> f(F);
    return symmetrize(f * Tensor<2, 3>(T) * f);
  }
} // namespace FrictionalContact
