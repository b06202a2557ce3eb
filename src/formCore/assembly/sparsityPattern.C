/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of sparsityPattern.H: Equation numbering and the fixed
    sparse structure of the Newton matrices.
\*---------------------------------------------------------------------------*/
#include "sparsityPattern.H"
#include "formError.H"
#include <algorithm>

void form::dofNumbering::build(const std::vector<bool>& constrained)
{
    const int n = int(constrained.size());
    equation.assign(n, 0);
    freeDofs.clear();
    prescribedDofs.clear();
    for (int d = 0; d < n; ++d)
    {
        if (constrained[d])
        {
            equation[d] = -1 - int(prescribedDofs.size());
            prescribedDofs.push_back(d);
        }
        else
        {
            equation[d] = int(freeDofs.size());
            freeDofs.push_back(d);
        }
    }
}


namespace
{

// Fill a compressed column matrix from sorted row lists
void setStructure
(
    form::sparseMatrix& K,
    int nRows,
    const std::vector<std::vector<int>>& columns
)
{
    std::size_t nnz = 0;
    for (const auto& c : columns) nnz += c.size();

    K.resize(nRows, int(columns.size()));
    K.resizeNonZeros(Eigen::Index(nnz));
    int* outer = K.outerIndexPtr();
    int* inner = K.innerIndexPtr();
    double* values = K.valuePtr();
    std::size_t p = 0;
    outer[0] = 0;
    for (std::size_t j = 0; j < columns.size(); ++j)
    {
        for (int row : columns[j])
        {
            inner[p] = row;
            values[p] = 0;
            ++p;
        }
        outer[j + 1] = int(p);
    }
}


// Position of row in column col of a compressed matrix (must exist)
std::size_t position(const form::sparseMatrix& K, int col, int row)
{
    const int* inner = K.innerIndexPtr();
    const int* begin = inner + K.outerIndexPtr()[col];
    const int* end = inner + K.outerIndexPtr()[col + 1];
    const int* it = std::lower_bound(begin, end, row);
    if (it == end || *it != row)
    {
        throw form::numericalError
        (
            "sparsityPattern: entry not in pattern (internal error)"
        );
    }
    return std::size_t(it - inner);
}

} // namespace


void form::sparsityPattern::build
(
    const dofNumbering& numbering,
    const std::vector<std::size_t>& offsets,
    const std::vector<int>& elementDofs,
    sparseMatrix& Kff,
    sparseMatrix& Kfp
)
{
    offsets_ = offsets;
    const int nElem = int(offsets.size()) - 1;
    const int nDofs = numbering.nDofs();
    const int nFree = numbering.nFree();

    // Elements of each dof (compressed)
    std::vector<std::size_t> dofStart(nDofs + 1, 0);
    for (int d : elementDofs)
    {
        if (d < 0 || d >= nDofs)
        {
            throw numericalError("sparsityPattern: element dof out of range");
        }
        ++dofStart[d + 1];
    }
    for (int d = 0; d < nDofs; ++d) dofStart[d + 1] += dofStart[d];
    std::vector<int> dofElements(dofStart[nDofs]);
    {
        std::vector<std::size_t> fill(dofStart.begin(), dofStart.end() - 1);
        for (int e = 0; e < nElem; ++e)
        {
            for (std::size_t k = offsets[e]; k < offsets[e + 1]; ++k)
            {
                dofElements[fill[elementDofs[k]]++] = e;
            }
        }
    }

    // Rows (free equations) coupled to each column dof; a stamp array
    // removes duplicates without a set
    std::vector<std::vector<int>> ffColumns(nFree);
    std::vector<std::vector<int>> fpColumns(numbering.nPrescribed());
    std::vector<int> stamp(nFree, -1);
    for (int c = 0; c < nDofs; ++c)
    {
        const int eqC = numbering.equation[c];
        std::vector<int>& rows = eqC >= 0 ? ffColumns[eqC] : fpColumns[-1 - eqC];
        for (std::size_t k = dofStart[c]; k < dofStart[c + 1]; ++k)
        {
            const int e = dofElements[k];
            for (std::size_t m = offsets[e]; m < offsets[e + 1]; ++m)
            {
                const int eqR = numbering.equation[elementDofs[m]];
                if (eqR >= 0 && stamp[eqR] != c)
                {
                    stamp[eqR] = c;
                    rows.push_back(eqR);
                }
            }
        }
        std::sort(rows.begin(), rows.end());
    }
    setStructure(Kff, nFree, ffColumns);
    setStructure(Kfp, nFree, fpColumns);

    // Greedy colouring in element order: the first colour not used by an
    // element already coloured that shares a dof (4 colours for structured
    // quads)
    {
        std::vector<int> colour(nElem, -1);
        std::vector<int> usedBy;   // usedBy[c] == e: colour c taken near e
        colours_.clear();
        for (int e = 0; e < nElem; ++e)
        {
            for (std::size_t m = offsets[e]; m < offsets[e + 1]; ++m)
            {
                const int d = elementDofs[m];
                for (std::size_t k = dofStart[d]; k < dofStart[d + 1]; ++k)
                {
                    const int c = colour[dofElements[k]];
                    if (c >= 0) usedBy[c] = e;
                }
            }
            int c = 0;
            while (c < int(usedBy.size()) && usedBy[c] == e) ++c;
            if (c == int(usedBy.size()))
            {
                usedBy.push_back(-1);
                colours_.emplace_back();
            }
            colour[e] = c;
            colours_[c].push_back(e);
        }
    }

    // Scatter maps
    codeOffsets_.assign(nElem + 1, 0);
    for (int e = 0; e < nElem; ++e)
    {
        const std::size_t n = offsets[e + 1] - offsets[e];
        codeOffsets_[e + 1] = codeOffsets_[e] + n*n;
    }
    codes_.assign(codeOffsets_[nElem], skip);
    for (int e = 0; e < nElem; ++e)
    {
        const int n = nElementDofs(e);
        const int* dofs = elementDofs.data() + offsets[e];
        int* code = codes_.data() + codeOffsets_[e];
        for (int b = 0; b < n; ++b)
        {
            const int eqC = numbering.equation[dofs[b]];
            for (int a = 0; a < n; ++a)
            {
                const int eqR = numbering.equation[dofs[a]];
                if (eqR < 0) continue;
                code[a + n*b] =
                    eqC >= 0
                  ? int(position(Kff, eqC, eqR))
                  : fpCode(position(Kfp, -1 - eqC, eqR));
            }
        }
    }
}
