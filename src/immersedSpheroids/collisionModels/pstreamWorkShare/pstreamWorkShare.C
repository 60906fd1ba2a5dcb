/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "pstreamWorkShare.H"
#include "processCpuTime.H"
#include "Pstream.H"
#include "List.H"
#include "ops.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

int Foam::pstreamWorkShare::rank() const
{
    return Pstream::myProcNo();
}


int Foam::pstreamWorkShare::size() const
{
    return Pstream::nProcs();
}


std::vector<char> Foam::pstreamWorkShare::allGather
(
    const std::vector<char>& local
) const
{
    const double cpu0 = immersedSpheroids::processCpuTime();
    List<List<char>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = List<char>(local.begin(), local.end());
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    std::size_t total = 0;
    for (const List<char>& block : all)
    {
        total += block.size();
    }
    std::vector<char> out;
    out.reserve(total);
    for (const List<char>& block : all)
    {
        out.insert(out.end(), block.begin(), block.end());
    }
    cpu_ += immersedSpheroids::processCpuTime() - cpu0;
    return out;
}


void Foam::pstreamWorkShare::minimum
(
    std::vector<collision::Scalar>& values
) const
{
    // gathered to the master and its answer sent: the same bits on every rank
    const double cpu0 = immersedSpheroids::processCpuTime();
    List<scalar> all(values.begin(), values.end());
    Pstream::listCombineGather(all, minEqOp<scalar>());
    Pstream::listCombineScatter(all);
    std::copy(all.begin(), all.end(), values.begin());
    cpu_ += immersedSpheroids::processCpuTime() - cpu0;
}


// ************************************************************************* //
