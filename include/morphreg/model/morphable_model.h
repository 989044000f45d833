// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file morphable_model.h
 *  \brief The multi-region statistical shape model of docs/method.md ("The multi-region
 *  shape model"): p_i = M_i m + mu_i.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/component_selection.h>

#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief One region R_j of a multi-region model: its (grown) vertex set, their blending weights and the
 *  region's PCA of the unweighted vertex positions.
 */
struct ModelRegion
{
  std::string name; ///< e.g. "nose"
  /** \brief Global vertex indices, strictly increasing. Local row r of the region is vertex vertices[r]. */
  std::vector<int> vertices;
  /** \brief Blending weight w_ij of each region vertex (same order), in [0, 1]. */
  Eigen::VectorXd weights;
  /** \brief 3B x P basis: rows 3r, 3r+1, 3r+2 are x, y, z of local vertex r. Orthonormal columns when made
   *  by ModelBuilder or loaded from a file.
   */
  Eigen::MatrixXd basis;
  /** \brief Variance (mm^2) of each basis column, descending. */
  Eigen::VectorXd variances;
};

/** \brief One non-zero block of a vertex's shape rows M_i: region \a region, local row \a row of that region's
 *  basis, blending weight \a weight. M_i = sum over entries of weight * [0 .. basis rows of (region,row) .. 0].
 */
struct RegionEntry
{
  int region;    ///< the region index
  int row;       ///< the vertex's local row in that region
  double weight; ///< the vertex's blending weight in that region
};

/** \brief A vertex in exactly two regions a and b: its smoothness-prior rows are
 *  Gamma_i m = P_i^(a) m_a - P_i^(b) m_b (unweighted basis rows; thesis eq. 40).
 */
struct GammaPair
{
  int vertex;   ///< the shared vertex
  int region_a; ///< the first of its two regions
  int row_a;    ///< its local row in region_a
  int region_b; ///< the second of its two regions
  int row_b;    ///< its local row in region_b
};

/** \brief Weighting of the shape regulariser Lambda (thesis eq. 42). */
enum class ShapePrior
{
  identity,       ///< Lambda = I: coefficients are penalised in mm
  inverse_std_dev ///< Lambda = diag(1 / sqrt(variance)): a prior in units of standard deviations
};

/** \brief A multi-region PCA shape model in a fixed triangle topology (mm by default).
 *
 *  A model vertex is p_i = mu_i + M_i m (docs/method.md, "A model vertex"), with m the stacked coefficients of the
 *  selected components of all regions and M_i the blending-weighted rows of the region bases that contain
 *  vertex i. Coefficients are in mm along orthonormal basis vectors; their prior is N(0, variance).
 *  A plain (global) PCA model is the special case of one region holding every vertex with weight 1.
 *  Inner-loop accessors (vertexEntries, regionRows, gammaPairs) do not validate their arguments; generate,
 *  project and the other whole-model functions do.
 *
 *  \code
 *  morphreg::MorphableModel::ConstPtr model = morphreg::loadModel ("head.h5");
 *  const morphreg::ComponentSelection sel = model->firstComponents (10);   // 10 per region
 *  Eigen::VectorXd m = Eigen::VectorXd::Zero (sel.total ());
 *  for (const auto& e : model->vertexEntries (i))                          // p_i = mu_i + M_i m
 *    p += e.weight * model->regionRows (e.region, e.row, sel.count (e.region))
 *                    * m.segment (sel.offset (e.region), sel.count (e.region));
 *  \endcode
 */
class MorphableModel
{
public:
  using Ptr = std::shared_ptr<MorphableModel>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const MorphableModel>; ///< shared pointer to const
  /** \brief Row-major dense matrix: the 3 rows of a vertex are contiguous. */
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  /** \brief A contiguous range of RegionEntry (the non-zero blocks of one vertex's M_i). */
  struct EntryRange
  {
    const RegionEntry* first; ///< the first entry
    const RegionEntry* last;  ///< one past the last entry

    /** \brief Start of the range.
     *  \return first
     */
    const RegionEntry*
    begin () const
    {
      return first;
    }

    /** \brief End of the range.
     *  \return last
     */
    const RegionEntry*
    end () const
    {
      return last;
    }

    /** \brief Number of entries: the regions the vertex lies in.
     *  \return last - first
     */
    int
    size () const
    {
      return static_cast<int> (last - first);
    }
  };

  /** \brief Least-squares coefficients of a shape and how well the model reproduces it. */
  struct Projection
  {
    Eigen::VectorXd coefficients;    ///< the stacked coefficients of the selection
    Eigen::Matrix3Xd reconstruction; ///< the model instance they give (3 x N)
    double rms_error = 0.0;          ///< RMS vertex distance (mm) between the shape and its reconstruction
    double max_error = 0.0;          ///< largest vertex distance (mm)
  };

  /** \brief Builds a model and its per-vertex index. Throws InvalidInputError if the triangles or mean are
   *  invalid, a region's vertices are unsorted or out of range, its basis, weights or variances have the
   *  wrong size or non-finite values, a weight is outside [0, 1], or a vertex's weights do not sum to 1.
   *  \param[in] triangles 3 x M vertex indices
   *  \param[in] mean 3N interleaved x, y, z of the mean shape
   *  \param[in] regions at least one region; every vertex must lie in one
   */
  MorphableModel (TriangleMesh::Triangles triangles, Eigen::VectorXd mean, std::vector<ModelRegion> regions);

  /** \brief A plain PCA model: one region "global" with every vertex at weight 1, and the same basis as its
   *  global (statismo) part.
   *  \param[in] triangles 3 x M vertex indices
   *  \param[in] mean 3N interleaved x, y, z of the mean shape
   *  \param[in] basis 3N x k orthonormal components
   *  \param[in] variances the k component variances (mm^2)
   *  \return the model
   */
  static Ptr
  fromGlobalPca (TriangleMesh::Triangles triangles, Eigen::VectorXd mean, Eigen::MatrixXd basis,
                 Eigen::VectorXd variances);

  // ---- topology and mean -------------------------------------------------------------------------------

  /** \brief The number of vertices N.
   *  \return N
   */
  Eigen::Index
  numVertices () const
  {
    return mean_.size () / 3;
  }

  /** \brief The model's triangles.
   *  \return 3 x M vertex indices
   */
  const TriangleMesh::Triangles&
  triangles () const
  {
    return triangles_;
  }

  /** \brief The mean shape mu as 3N interleaved coordinates.
   *  \return mu
   */
  const Eigen::VectorXd&
  mean () const
  {
    return mean_;
  }

  /** \brief mu_i of vertex \a vertex.
   *  \param[in] vertex the vertex index
   *  \return its mean position
   */
  Eigen::Vector3d
  meanVertex (int vertex) const
  {
    return mean_.segment<3> (3 * static_cast<Eigen::Index> (vertex));
  }

  /** \brief The mean shape as a mesh.
   *  \return the mean vertices with the model's triangles
   */
  TriangleMesh
  meanMesh () const;

  // ---- regions and components --------------------------------------------------------------------------

  /** \brief The number of regions K.
   *  \return K
   */
  int
  numRegions () const
  {
    return static_cast<int> (regions_.size ());
  }

  /** \brief One region.
   *  \param[in] index the region index, 0 <= index < numRegions ()
   *  \return the region
   */
  const ModelRegion&
  region (int index) const
  {
    return regions_[index];
  }

  /** \brief All regions.
   *  \return the regions, in index order
   */
  const std::vector<ModelRegion>&
  regions () const
  {
    return regions_;
  }

  /** \brief Index of the region called \a name, or -1.
   *  \param[in] name the region's name
   *  \return its index, or -1 if there is none
   */
  int
  findRegion (const std::string& name) const;

  /** \brief Every component of every region.
   *  \return the selection
   */
  ComponentSelection
  allComponents () const;

  /** \brief The first min(k, available) components of each region.
   *  \param[in] k components per region
   *  \return the selection
   */
  ComponentSelection
  firstComponents (int k) const;

  /** \brief The first min(k[j], available) components of region j; throws InvalidInputError if k has the
   *  wrong length or a negative entry.
   *  \param[in] k components of each region
   *  \return the selection
   */
  ComponentSelection
  firstComponents (const std::vector<int>& k) const;

  /** \brief Throws InvalidInputError naming \a what if \a selection does not fit this model (region count,
   *  more components than a region has) or \a coefficients (if given) has not selection.total() entries.
   *  \param[in] selection the selection to check
   *  \param[in] coefficients stacked coefficients to check against it, or nullptr
   *  \param[in] what the caller, for the message
   */
  void
  requireCompatible (const ComponentSelection& selection, const Eigen::VectorXd* coefficients,
                     const std::string& what) const;

  // ---- per-vertex sparse shape rows (inner loop) ----------------------------------------------------------

  /** \brief The non-zero blocks of M_i: the regions vertex \a vertex belongs to, with local row and weight.
   *  \param[in] vertex the vertex index (not checked)
   *  \return one entry per region of the vertex
   */
  EntryRange
  vertexEntries (int vertex) const
  {
    return {entries_.data () + entry_offsets_[vertex], entries_.data () + entry_offsets_[vertex + 1]};
  }

  /** \brief The 3 x \a count unweighted basis rows P_i^(region) of local row \a row (first \a count columns).
   *  \param[in] region the region index (not checked)
   *  \param[in] row the vertex's local row in the region
   *  \param[in] count the number of leading components
   *  \return a view into the region's basis
   */
  Eigen::Block<const Eigen::MatrixXd>
  regionRows (int region, int row, int count) const
  {
    return regions_[region].basis.block (3 * static_cast<Eigen::Index> (row), 0, 3, count);
  }

  /** \brief The dense 3 x P weighted shape rows M_i for \a selection (convenience; allocates).
   *  \param[in] vertex the vertex index
   *  \param[in] selection the components
   *  \return M_i
   */
  Eigen::Matrix3Xd
  shapeRows (int vertex, const ComponentSelection& selection) const;

  /** \brief The whole model matrix H (3N x P, row-major) for \a selection: M_i is
   *  shapeMatrix.middleRows (3 * i, 3), contiguous in memory. Build it once per fit, outside the inner loop.
   *  \param[in] selection the components
   *  \return H
   */
  RowMatrix
  shapeMatrix (const ComponentSelection& selection) const;

  /** \brief p_i = mu_i + M_i m for one vertex (no validation).
   *  \param[in] vertex the vertex index
   *  \param[in] coefficients the stacked coefficients m
   *  \param[in] selection the components m refers to
   *  \return p_i
   */
  Eigen::Vector3d
  vertex (int vertex, const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const;

  // ---- priors -------------------------------------------------------------------------------------------

  /** \brief Every vertex that lies in exactly two regions (the rows of Gamma, thesis eq. 40-41).
   *  \return the pairs, by vertex
   */
  const std::vector<GammaPair>&
  gammaPairs () const
  {
    return gamma_pairs_;
  }

  /** \brief The smoothness-prior matrix Gamma (3L x P, row-major) for \a selection: rows 3l..3l+2 are
   *  P_i^(a) in region a's columns and -P_i^(b) in region b's columns for gamma pair l.
   *  \param[in] selection the components
   *  \return Gamma
   */
  RowMatrix
  gammaMatrix (const ComponentSelection& selection) const;

  /** \brief Gamma m: one column P_i^(a) m_a - P_i^(b) m_b per gamma pair (3 x L).
   *  \param[in] coefficients the stacked coefficients m
   *  \param[in] selection the components m refers to
   *  \return the disagreement of the two regions at each shared vertex (mm)
   */
  Eigen::Matrix3Xd
  gammaResiduals (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const;

  /** \brief The diagonal of Lambda for \a selection (thesis eq. 42): ones, or 1 / sqrt(variance) (variances
   *  are floored at 1e-12 of the largest so a zero-variance component gets a large but finite weight).
   *  \param[in] selection the components
   *  \param[in] prior identity or inverse standard deviations
   *  \return one weight per selected component
   */
  Eigen::VectorXd
  lambdaDiagonal (const ComponentSelection& selection, ShapePrior prior) const;

  /** \brief The variances of the selected components, stacked like the coefficients.
   *  \param[in] selection the components
   *  \return one variance (mm^2) per selected component
   */
  Eigen::VectorXd
  variances (const ComponentSelection& selection) const;

  // ---- instances ----------------------------------------------------------------------------------------

  /** \brief Vertex positions (3 x N) for stacked \a coefficients of \a selection.
   *  \param[in] coefficients the stacked coefficients m
   *  \param[in] selection the components m refers to
   *  \return the instance's vertices
   */
  Eigen::Matrix3Xd
  generate (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const;

  /** \brief Vertex positions for coefficients of all components.
   *  \param[in] coefficients one coefficient per component of every region
   *  \return the instance's vertices
   */
  Eigen::Matrix3Xd
  generate (const Eigen::VectorXd& coefficients) const
  {
    return generate (coefficients, allComponents ());
  }

  /** \brief The instance as a mesh in the model topology.
   *  \param[in] coefficients the stacked coefficients m
   *  \param[in] selection the components m refers to
   *  \return the mesh
   */
  TriangleMesh
  generateMesh (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const;

  /** \brief The instance as a pcl::PolygonMesh (PointNormal vertices, normals from the triangles).
   *  \param[in] coefficients the stacked coefficients m
   *  \param[in] selection the components m refers to
   *  \return the PCL mesh
   */
  pcl::PolygonMesh
  generatePolygonMesh (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const;

  /** \brief The instance's vertices as a cloud (one point per vertex, in vertex order); point types with
   *  normals get area-weighted vertex normals.
   *  \param[in] coefficients the stacked coefficients m
   *  \param[in] selection the components m refers to
   *  \return the cloud
   */
  template <typename PointT>
  typename pcl::PointCloud<PointT>::Ptr
  generateCloud (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const;

  /** \brief Coefficients drawn from N(0, variance) for each selected component.
   *  \param[in,out] rng the random generator
   *  \param[in] selection the components
   *  \return the stacked coefficients
   */
  Eigen::VectorXd
  sampleCoefficients (std::mt19937_64& rng, const ComponentSelection& selection) const;

  /** \brief Least-squares coefficients of \a shape (3 x N, in the model's frame and topology) for
   *  \a selection, minimising ||H m - (x - mu)||^2 + regularization * ||Lambda m||^2 (thesis eq. 8 when
   *  regularization is 0 and the basis is orthonormal). Throws InvalidInputError for a wrong vertex count or
   *  non-finite input, NumericalError if the system is singular.
   *  \param[in] shape the shape to project (3 x N, mm)
   *  \param[in] selection the components to use
   *  \param[in] regularization the weight of the prior term (0: plain least squares)
   *  \param[in] prior the weighting Lambda of the prior term
   *  \return the coefficients, the reconstruction and its error
   */
  Projection
  project (const Eigen::Matrix3Xd& shape, const ComponentSelection& selection, double regularization = 0.0,
           ShapePrior prior = ShapePrior::inverse_std_dev) const;

  /** \brief As project(), for a mesh that must share the model's topology.
   *  \param[in] mesh the shape to project
   *  \param[in] selection the components to use
   *  \param[in] regularization the weight of the prior term (0: plain least squares)
   *  \param[in] prior the weighting Lambda of the prior term
   *  \return the coefficients, the reconstruction and its error
   */
  Projection
  project (const TriangleMesh& mesh, const ComponentSelection& selection, double regularization = 0.0,
           ShapePrior prior = ShapePrior::inverse_std_dev) const;

  // ---- global PCA part (written to the statismo /model group) --------------------------------------------

  /** \brief Sets the global PCA (3N x k orthonormal basis and its variances) that statismo tools read.
   *  \param[in] basis 3N x k orthonormal columns
   *  \param[in] variances the k variances (mm^2)
   */
  void
  setGlobalPca (Eigen::MatrixXd basis, Eigen::VectorXd variances);

  /** \brief The global PCA's basis.
   *  \return 3N x k orthonormal columns
   */
  const Eigen::MatrixXd&
  globalBasis () const
  {
    return global_basis_;
  }

  /** \brief The global PCA's variances.
   *  \return k variances (mm^2)
   */
  const Eigen::VectorXd&
  globalVariances () const
  {
    return global_variances_;
  }

  /** \brief Isotropic noise variance (mm^2) of the probabilistic PCA (statismo's noiseVariance).
   *  \param[in] variance the variance, >= 0
   */
  void
  setNoiseVariance (double variance);

  /** \brief Isotropic noise variance of the probabilistic PCA.
   *  \return the variance (mm^2)
   */
  double
  noiseVariance () const
  {
    return noise_variance_;
  }

  // ---- annotations --------------------------------------------------------------------------------------

  /** \brief Named landmark vertices; throws InvalidInputError if an index is out of range or a name is empty.
   *  \param[in] landmarks id -> vertex index
   */
  void
  setLandmarks (LandmarkVertices landmarks);

  /** \brief Named landmark vertices.
   *  \return id -> vertex index
   */
  const LandmarkVertices&
  landmarks () const
  {
    return landmarks_;
  }

  /** \brief Vertex of landmark \a name; throws InvalidInputError listing the model's landmarks if unknown.
   *  \param[in] name the landmark id
   *  \return its vertex index
   */
  int
  landmarkVertex (const std::string& name) const;

  /** \brief The mid-sagittal profile line as an ordered vertex list; indices are validated.
   *  \param[in] vertices the line's vertices in order along it
   */
  void
  setProfileLine (std::vector<int> vertices);

  /** \brief The mid-sagittal profile line.
   *  \return its vertices in order (empty if the model has none)
   */
  const std::vector<int>&
  profileLine () const
  {
    return profile_line_;
  }

  /** \brief Length unit of the model's coordinates ("mm" unless an importer says otherwise).
   *  \param[in] units the unit's symbol
   */
  void
  setUnits (std::string units);

  /** \brief Length unit of the model's coordinates.
   *  \return the unit's symbol
   */
  const std::string&
  units () const
  {
    return units_;
  }

  /** \brief Free-form key/value metadata (source, licence, builder settings).
   *  \param[in] metadata key -> value
   */
  void
  setMetadata (std::map<std::string, std::string> metadata);

  /** \brief Free-form key/value metadata.
   *  \return key -> value
   */
  const std::map<std::string, std::string>&
  metadata () const
  {
    return metadata_;
  }

private:
  void
  validateRegion (const ModelRegion& region, int index) const;

  void
  buildVertexIndex ();

  Eigen::Matrix3Xd
  displacements (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const;

  TriangleMesh::Triangles triangles_;
  Eigen::VectorXd mean_;
  std::vector<ModelRegion> regions_;
  std::vector<int> entry_offsets_;
  std::vector<RegionEntry> entries_;
  std::vector<GammaPair> gamma_pairs_;
  Eigen::MatrixXd global_basis_;
  Eigen::VectorXd global_variances_;
  double noise_variance_ = 0.0;
  LandmarkVertices landmarks_;
  std::vector<int> profile_line_;
  std::string units_ = "mm";
  std::map<std::string, std::string> metadata_;
};

} // namespace morphreg

// Bodies in impl/morphable_model.hpp (include it for other point types); instantiated in the library for:
/// \cond
#define MORPHREG_DECLARE_MORPHABLE_MODEL(T)                                                                            \
  extern template pcl::PointCloud<T>::Ptr morphreg::MorphableModel::generateCloud<T> (                                 \
      const Eigen::VectorXd&, const morphreg::ComponentSelection&) const;
MORPHREG_DECLARE_MORPHABLE_MODEL (pcl::PointXYZ)
MORPHREG_DECLARE_MORPHABLE_MODEL (pcl::PointNormal)
MORPHREG_DECLARE_MORPHABLE_MODEL (pcl::PointXYZRGBNormal)
#undef MORPHREG_DECLARE_MORPHABLE_MODEL
/// \endcond
