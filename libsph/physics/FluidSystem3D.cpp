#include "physics/FluidSystem.tpp"

template class sph::FluidSystem<3>;
