(* One test executable, one alcotest run: every suite is listed here. *)
let () =
  Alcotest.run "camlray"
    [
      Test_vec3.tests;
      Test_transform.tests;
      Test_hits.tests;
      Test_camera.tests;
      Test_render.tests;
      Test_cli.tests;
      Test_pov_scenes.tests;
      Test_workflow.tests;
      Test_robust.tests;
      Test_numerics.tests;
      Test_bench.tests;
      Test_access.tests;
      Test_image.tests;
      Test_value.tests;
      Test_supplier.tests;
      Test_fn.tests;
      Test_shape.tests;
      Test_bvh.tests;
      Test_object.tests;
      Test_geom_render.tests;
      Test_spline.tests;
      Test_parse.tests;
      Test_errors.tests;
      Test_golden.tests;
      Test_printer.tests;
      Test_lang.tests;
      Test_sampler.tests;
      Test_bsdf.tests;
      Test_path.tests;
    ]
