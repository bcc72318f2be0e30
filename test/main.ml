(* One test executable, one alcotest run: every suite is listed here. *)
let () =
  Alcotest.run "camlray"
    [
      Test_vec3.tests;
      Test_image.tests;
      Test_value.tests;
      Test_supplier.tests;
      Test_fn.tests;
      Test_spline.tests;
      Test_parse.tests;
      Test_errors.tests;
    ]
