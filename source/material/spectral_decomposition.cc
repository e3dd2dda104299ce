#include <frictional_contact/model/spectral_decomposition.h>

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
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int a = 0; a < 3; ++a)
          result[i][j] += d[a] * vectors[i][a] * vectors[j][a];
    return result;
  }



  SymmetricTensor<2, 3>
  congruence(const SymmetricTensor<2, 3> &F, const SymmetricTensor<2, 3> &T)
  {
    const Tensor<2, 3> f(F);
    return symmetrize(f * Tensor<2, 3>(T) * f);
  }
} // namespace FrictionalContact
