/**
 * @file bodyOutput.hpp
 * @brief Output of the immersed bodies (pure C++17 + the serial HDF5 C library, no OpenFOAM):
 *        HDF5 time series (TimeSeries.hpp) and VTK surfaces with ParaView series files
 *        (SurfaceVtk.hpp). No HDF5 header is included: users compile without HDF5's include
 *        folder and link -lbodyOutput -lhdf5 (see src/bodyOutput/CMakeLists.txt).
 */
#ifndef BODYOUTPUT_BODYOUTPUT_HPP
#define BODYOUTPUT_BODYOUTPUT_HPP

#include "bodyOutput/SurfaceVtk.hpp"
#include "bodyOutput/TimeSeries.hpp"

#endif  // BODYOUTPUT_BODYOUTPUT_HPP
