// Prints Reparam's option defaults (CTest options.defaults)
Printf("CompoundParametrization=%g CompoundRepair=%g CompoundFillHoles=%g CompoundReport=%g",
       Mesh.CompoundParametrization, Mesh.CompoundRepair,
       Mesh.CompoundFillHoles, Mesh.CompoundReport);
Printf(StrCat("CompoundReportFile='", Mesh.CompoundReportFile, "'"));
