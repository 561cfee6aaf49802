// Prints Reparam's option defaults (CTest options.defaults)
Printf("CompoundParametrization=%g CompoundRepair=%g CompoundFillHoles=%g",
       Mesh.CompoundParametrization, Mesh.CompoundRepair,
       Mesh.CompoundFillHoles);
