/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of umfpackSolver.H: Sparse LU factorisation P R K Q = L U
    (SuiteSparse UMFPACK through Eigen::UmfPackLU) with the METIS or the
    AMD column ordering (umfpackSolver.H says which).
\*---------------------------------------------------------------------------*/
#include "umfpackSolver.H"
#include "formError.H"
#include <Eigen/UmfPackSupport>
#include <cmath>
#include <vector>

namespace form
{

// Access to UMFPACK's Numeric object and Info array held by Eigen's wrapper
struct umfpackLU
:
    public Eigen::UmfPackLU<sparseMatrix>
{
    void* numeric() const { return m_numeric; }
    double controlValue(int i) const { return m_control(i); }
    using Eigen::UmfPackLU<sparseMatrix>::info;
    double infoValue(int i) const { return m_umfpackInfo(i); }
};

struct umfpackSolver::impl
{
    //- An ordering and a strategy of UMFPACK
    struct choice
    {
        int ordering = UMFPACK_ORDERING_AMD;
        int strategy = UMFPACK_STRATEGY_AUTO;
    };

    //- The factorisation, and the other candidates' analyses while the
    //  first factorisation compares them (else empty)
    std::unique_ptr<umfpackLU> lu = std::make_unique<umfpackLU>();
    std::vector<std::unique_ptr<umfpackLU>> others;
    // UMFPACK's solve may read the matrix again (iterative refinement, off
    // below), so the factorised matrix is kept here rather than referenced
    sparseMatrix K;
    bool analysed = false;
    bool factorised = false;
    //- The choice of a first factorisation (valid: one was made), and the
    //  nonzeros of its matrix
    bool valid = false;
    choice chosen;
    double chosenNonZeros = 0;

    //- Symbolic analysis of K with a choice into a new object
    std::unique_ptr<umfpackLU> analyse(choice c) const
    {
        auto lu = std::make_unique<umfpackLU>();
        lu->umfpackControl()(UMFPACK_ORDERING) = c.ordering;
        lu->umfpackControl()(UMFPACK_STRATEGY) = c.strategy;
        // No iterative refinement: Newton's next iteration refines, and
        // each refinement step costs another solve and a product with K
        // (UMFPACK's default, 2 steps, made a transient FSI step's solves
        // 3.2 times slower: 4.0 -> 1.25 s over 103 kept-tangent iterations
        // on FSI1's mesh, the same iterations, tip to 2e-11)
        lu->umfpackControl()(UMFPACK_IRSTEP) = 0;
        lu->analyzePattern(K);
        if (lu->info() != Eigen::Success)
        {
            throw numericalError
            (
                "umfpack: symbolic analysis failed, status "
              + std::to_string(int(lu->infoValue(UMFPACK_STATUS)))
            );
        }
        return lu;
    }

    static bool metis(const umfpackLU& lu)
    {
        return int(lu.infoValue(UMFPACK_ORDERING_USED)) == UMFPACK_ORDERING_METIS;
    }

    static bool symmetric(const umfpackLU& lu)
    {
        return
            int(lu.infoValue(UMFPACK_STRATEGY_USED))
         == UMFPACK_STRATEGY_SYMMETRIC;
    }

    //- The choice a factorisation was made with (the strategy as asked:
    //  auto stays auto, so that it decides again for a later pattern)
    choice choiceOf(const umfpackLU& lu) const
    {
        return
        {
            metis(lu) ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD,
            int(lu.controlValue(UMFPACK_STRATEGY))
        };
    }
};

namespace
{

// True if a row or column of K has more than 10 sqrt(n) entries: the
// threshold above which AMD (and so UMFPACK's AMD/COLAMD ordering) treats
// it as dense and orders it last (Amestoy, Davis & Duff, ACM TOMS 30,
// 2004). METIS on the pattern of K + K^T has no such treatment: a dense
// border widens every front to its width.
bool hasDenseRowOrColumn(const form::sparseMatrix& K)
{
    const double dense = 10*std::sqrt(double(K.rows()));
    std::vector<int> rowCount(K.rows(), 0);
    for (int k = 0; k < K.outerSize(); ++k)
    {
        const int n = K.outerIndexPtr()[k + 1] - K.outerIndexPtr()[k];
        if (n > dense) return true;
        for (int i = K.outerIndexPtr()[k]; i < K.outerIndexPtr()[k + 1]; ++i)
        {
            if (++rowCount[K.innerIndexPtr()[i]] > dense) return true;
        }
    }
    return false;
}

} // namespace

} // namespace form


form::umfpackSolver::umfpackSolver(ordering o)
:
    impl_(std::make_unique<impl>()),
    ordering_(o)
{
}


form::umfpackSolver::~umfpackSolver() = default;


void form::umfpackSolver::analyzePattern(const sparseMatrix& K)
{
    if (K.rows() != K.cols())
    {
        throw numericalError("umfpack: matrix is not square");
    }
    using choice = impl::choice;
    impl& m = *impl_;
    m.K = K;
    m.K.makeCompressed();
    m.analysed = false;
    m.factorised = false;
    m.others.clear();
    if (ordering_ == ordering::amd)
    {
        m.lu = m.analyse({UMFPACK_ORDERING_AMD, UMFPACK_STRATEGY_AUTO});
    }
    else if (ordering_ == ordering::metis)
    {
        m.lu = m.analyse({UMFPACK_ORDERING_METIS, UMFPACK_STRATEGY_AUTO});
    }
    else if (ordering_ == ordering::symmetricAmd)
    {
        m.lu = m.analyse({UMFPACK_ORDERING_AMD, UMFPACK_STRATEGY_SYMMETRIC});
    }
    else if (hasDenseRowOrColumn(m.K))
    {
        m.lu = m.analyse({UMFPACK_ORDERING_AMD, UMFPACK_STRATEGY_AUTO});
    }
    else if
    (
        m.valid
     && std::abs(m.K.nonZeros() - m.chosenNonZeros) <= 0.25*m.chosenNonZeros
    )
    {
        m.lu = m.analyse(m.chosen);
    }
    else
    {
        // The first pattern, or one of another size
        auto amd = m.analyse({UMFPACK_ORDERING_AMD, UMFPACK_STRATEGY_AUTO});
        if (!impl::symmetric(*amd))
        {
            // UMFPACK took the unsymmetric strategy (a pattern less than
            // half symmetric: the ALE fluid's matrices). Its METIS orders
            // K^T K (1.5-2 times AMD's flops there), but its symmetric
            // strategy (AMD on K + K^T) is a candidate, and its flop
            // estimate is no guide (50-100 times the count on the FSI
            // matrices): the first numeric factorisation decides
            m.lu = std::move(amd);
            m.others.push_back
            (
                m.analyse({UMFPACK_ORDERING_AMD, UMFPACK_STRATEGY_SYMMETRIC})
            );
        }
        else
        {
            // Both orderings. The symbolic flop estimates decide if they
            // differ by more than a factor 4 (the FSI matrix at rest:
            // 32), else the first numeric factorisation
            auto metis =
                m.analyse({UMFPACK_ORDERING_METIS, UMFPACK_STRATEGY_AUTO});
            const double fm = metis->infoValue(UMFPACK_FLOPS_ESTIMATE);
            const double fa = amd->infoValue(UMFPACK_FLOPS_ESTIMATE);
            const bool amdFirst = fa < fm;
            m.lu = std::move(amdFirst ? amd : metis);
            if (std::max(fm, fa) <= 4*std::min(fm, fa))
            {
                m.others.push_back(std::move(amdFirst ? metis : amd));
            }
        }
        if (m.others.empty())
        {
            m.chosen = m.choiceOf(*m.lu);
            m.valid = true;
            m.chosenNonZeros = m.K.nonZeros();
        }
    }
    m.analysed = true;
}


void form::umfpackSolver::factorize(const sparseMatrix& K)
{
    impl& m = *impl_;
    if (!m.analysed)
    {
        analyzePattern(K);
    }
    m.factorised = false;
    m.K = K;
    m.K.makeCompressed();
    const auto factor = [&](umfpackLU& lu)
    {
        lu.factorize(m.K);
        if (lu.info() != Eigen::Success)
        {
            const int status = lu.umfpackFactorizeReturncode();
            throw numericalError
            (
                std::string("umfpack: numeric factorisation failed (")
              + (
                    status == UMFPACK_WARNING_singular_matrix
                  ? "singular matrix"
                  : "status " + std::to_string(status)
                )
              + ")"
            );
        }
    };
    factor(*m.lu);
    if (!m.others.empty())
    {
        // The first factorisation with the other candidates too: the one
        // with fewest flops stays, for the later patterns as well (a
        // candidate that fails numerically drops out)
        for (auto& other : m.others)
        {
            try
            {
                factor(*other);
            }
            catch (const numericalError&)
            {
                continue;
            }
            if (other->infoValue(UMFPACK_FLOPS) < m.lu->infoValue(UMFPACK_FLOPS))
            {
                std::swap(m.lu, other);
            }
        }
        m.others.clear();
        m.chosen = m.choiceOf(*m.lu);
        m.valid = true;
        m.chosenNonZeros = m.K.nonZeros();
    }
    m.factorised = true;
}


form::vecX form::umfpackSolver::solve(const vecX& r)
{
    if (!impl_->factorised)
    {
        throw numericalError("umfpack: solve() called without factorisation");
    }
    vecX x = impl_->lu->solve(r);
    if (impl_->lu->info() != Eigen::Success || !x.allFinite())
    {
        throw numericalError("umfpack: solve failed");
    }
    return x;
}


form::linearSolver::factorStats form::umfpackSolver::stats() const
{
    // UMFPACK user guide, Info array of umfpack_numeric: nonzeros of L
    // and U, flop count
    if (!impl_->factorised) return {};
    return
    {
        impl_->lu->infoValue(UMFPACK_LNZ) + impl_->lu->infoValue(UMFPACK_UNZ),
        impl_->lu->infoValue(UMFPACK_FLOPS)
    };
}


double form::umfpackSolver::factorMemory() const
{
    if (!impl_->factorised || !impl_->lu->numeric()) return 0;
    int lnz = 0, unz = 0, nRow = 0, nCol = 0, nzUdiag = 0;
    umfpack_di_get_lunz
    (
        &lnz, &unz, &nRow, &nCol, &nzUdiag, impl_->lu->numeric()
    );
    return (double(lnz) + double(unz))*(sizeof(double) + sizeof(int));
}


bool form::umfpackSolver::usedMetis() const
{
    return impl_->analysed && impl::metis(*impl_->lu);
}


bool form::umfpackSolver::usedSymmetricStrategy() const
{
    return impl_->analysed && impl::symmetric(*impl_->lu);
}
