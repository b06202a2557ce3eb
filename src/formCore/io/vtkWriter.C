/*---------------------------------------------------------------------------*\
  formFoam: implicit finite-element forming with fluid-structure interaction
-------------------------------------------------------------------------------
Description
    Implementation of vtkWriter.H: Writes the solid mesh and results as VTK
    XML unstructured grids (.vtu) with true higher-order cells
    (VTK_BIQUADRATIC_QUAD for 9-node elements, VTK_QUAD for 4-node ones,
    VTK_TRIANGLE for the 3-node shells) and
    a .pvd collection that ParaView opens as a time series.
\*---------------------------------------------------------------------------*/
#include "vtkWriter.H"
#include "formError.H"
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <sys/stat.h>

void form::writeFileAtomic(const std::string& path, const std::string& text)
{
    const std::string tmp = path + ".tmp";
    {
        std::ofstream os(tmp);
        os << text;
        os.flush();
        os.close();
        if (!os)
        {
            std::remove(tmp.c_str());
            throw numericalError
            (
                "cannot write file " + tmp + " (disk full?)"
            );
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        throw numericalError("cannot rename " + tmp + " to " + path);
    }
}


form::vtkWriter::vtkWriter(const std::string& dir, const std::string& name)
:
    dir_(dir),
    name_(name)
{
    ::mkdir(dir_.c_str(), 0755);
}


void form::vtkWriter::resume(double time)
{
    series_.clear();
    next_ = 0;
    std::ifstream is(dir_ + "/" + name_ + ".pvd");
    const double tol = 1e-9*std::max(1.0, std::abs(time));
    for (std::string line; std::getline(is, line);)
    {
        const auto t0 = line.find("timestep=\"");
        const auto f0 = line.find("file=\"");
        if (t0 == std::string::npos || f0 == std::string::npos) continue;
        const double t = std::atof(line.c_str() + t0 + 10);
        const auto f1 = line.find('"', f0 + 6);
        const std::string file = line.substr(f0 + 6, f1 - f0 - 6);
        if (t > time + tol) continue;
        series_.emplace_back(t, file);
        // name_<index>.vtu
        const auto u = file.rfind('_');
        if (u != std::string::npos)
        {
            next_ = std::max(next_, std::atoi(file.c_str() + u + 1) + 1);
        }
    }
}


int form::vtkWriter::cellType(int nodesPerElement, int nDim)
{
    if (nDim == 2 && nodesPerElement == 4) return 9;    // VTK_QUAD
    if (nDim == 2 && nodesPerElement == 9) return 28;   // VTK_BIQUADRATIC_QUAD
    if (nDim == 3 && nodesPerElement == 4) return 9;    // VTK_QUAD (shells)
    if (nDim == 3 && nodesPerElement == 3) return 5;    // VTK_TRIANGLE (shells)
    if (nDim == 3 && nodesPerElement == 8) return 12;   // VTK_HEXAHEDRON
    if (nDim == 3 && nodesPerElement == 27) return 29;  // VTK_TRIQUADRATIC_HEX
    throw numericalError
    (
        "vtkWriter: no VTK cell for " + std::to_string(nodesPerElement)
      + "-node elements in " + std::to_string(nDim) + "D"
    );
}


void form::vtkWriter::write
(
    double time,
    const feMesh& mesh,
    const matX& U,
    const std::vector<elementResult>& results
)
{
    const int nPts = mesh.nNodes();
    const int nCells = mesh.nElements();
    std::ostringstream os;
    os << std::setprecision(9);
    os  << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\""
        << " byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << nPts
        << "\" NumberOfCells=\"" << nCells << "\">\n";

    os << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\""
       << " format=\"ascii\">\n";
    for (int i = 0; i < nPts; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            os << (d < mesh.nDim ? mesh.X(i, d) : 0.0) << (d < 2 ? ' ' : '\n');
        }
    }
    os << "</DataArray></Points>\n<Cells>\n"
       << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& b : mesh.blocks)
    {
        for (int e = 0; e < b.nElements(); ++e)
        {
            for (int k = 0; k < b.nodesPerElement; ++k)
            {
                os << b.nodes(e)[k] << (k + 1 < b.nodesPerElement ? ' ' : '\n');
            }
        }
    }
    os << "</DataArray>\n"
       << "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    long offset = 0;
    for (const auto& b : mesh.blocks)
    {
        for (int e = 0; e < b.nElements(); ++e)
        {
            offset += b.nodesPerElement;
            os << offset << '\n';
        }
    }
    os << "</DataArray>\n"
       << "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (const auto& b : mesh.blocks)
    {
        const int t = cellType(b.nodesPerElement, mesh.nDim);
        for (int e = 0; e < b.nElements(); ++e) os << t << '\n';
    }
    os << "</DataArray>\n</Cells>\n";

    os << "<PointData Vectors=\"displacement\">\n"
       << "<DataArray type=\"Float64\" Name=\"displacement\""
       << " NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (int i = 0; i < nPts; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            os << (d < U.cols() ? U(i, d) : 0.0) << (d < 2 ? ' ' : '\n');
        }
    }
    os << "</DataArray>\n</PointData>\n<CellData>\n";

    const auto tensorArray = [&](const std::string& name, auto get)
    {
        os << "<DataArray type=\"Float64\" Name=\"" << name << "\""
           << " NumberOfComponents=\"6\""
           << " ComponentName0=\"xx\" ComponentName1=\"yy\""
           << " ComponentName2=\"zz\" ComponentName3=\"xy\""
           << " ComponentName4=\"yz\" ComponentName5=\"xz\""
           << " format=\"ascii\">\n";
        for (const auto& r : results)
        {
            const vec6 s = toVoigtStress(get(r));
            for (int a = 0; a < 6; ++a) os << s(a) << (a < 5 ? ' ' : '\n');
        }
        os << "</DataArray>\n";
    };
    tensorArray("sigma", [](const elementResult& r) { return r.cauchy; });

    const auto scalarArray = [&](const char* name, auto get)
    {
        os << "<DataArray type=\"Float64\" Name=\"" << name
           << "\" format=\"ascii\">\n";
        for (const auto& r : results) os << get(r) << '\n';
        os << "</DataArray>\n";
    };
    scalarArray("sigmaEq", [](const elementResult& r)
    {
        const mat3 dev = r.cauchy - r.cauchy.trace()/3*mat3::Identity();
        return std::sqrt(1.5*(dev.array()*dev.array()).sum());
    });
    scalarArray("p", [](const elementResult& r) { return r.pressure; });
    scalarArray("epsilonEq",
        [](const elementResult& r) { return r.equivalentStrain; });
    // Shells: the current thickness (the section's times the mean thickness
    // stretch over the element's points: through the thickness and over it)
    bool shells = false;
    for (const auto& b : mesh.blocks) shells = shells || b.shell.thickness > 0;
    if (shells)
    {
        os << "<DataArray type=\"Float64\" Name=\"thickness\""
           << " format=\"ascii\">\n";
        std::size_t k = 0;
        for (const auto& b : mesh.blocks)
        {
            for (int e = 0; e < b.nElements(); ++e, ++k)
            {
                os << b.shell.thickness*results[k].meanThicknessStretch << '\n';
            }
        }
        os << "</DataArray>\n";
        // The mid-surface's principal logarithmic strains (the forming
        // limit diagram's axes, surfaceStrain.H)
        scalarArray("majorStrain",
            [](const elementResult& r) { return r.majorStrain; });
        scalarArray("minorStrain",
            [](const elementResult& r) { return r.minorStrain; });
        // The stress at the bottom, middle and top points (elementResult)
        const char* layer[3] = {"sigmaBottom", "sigmaMiddle", "sigmaTop"};
        for (int l = 0; l < 3; ++l)
        {
            tensorArray
            (
                layer[l],
                [l](const elementResult& r) { return r.shellLayers[l]; }
            );
        }
    }
    os << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";

    const std::string file = name_ + "_" + std::to_string(next_++) + ".vtu";
    writeFileAtomic(dir_ + "/" + file, os.str());
    series_.emplace_back(time, file);

    std::ostringstream pvd;
    pvd << std::setprecision(12)
        << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\""
        << " version=\"0.1\">\n<Collection>\n";
    for (const auto& s : series_)
    {
        pvd << "  <DataSet timestep=\"" << s.first << "\" file=\""
            << s.second << "\"/>\n";
    }
    pvd << "</Collection>\n</VTKFile>\n";
    writeFileAtomic(dir_ + "/" + name_ + ".pvd", pvd.str());
}
