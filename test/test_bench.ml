(* The benchmark's smoke run: every workload at small sizes, so the bench
   cannot rot (measurements are taken with make bench, never asserted). *)
let tests =
  ( "bench",
    [
      Alcotest.test_case "smoke run" `Quick (fun () ->
          let rows = Camlray_bench.Bench.run ~sizes:[ 10; 1000 ] ~width:32 ~height:24 () in
          Alcotest.(check int) "rows" 6 (List.length rows);
          List.iter
            (fun (r : Camlray_bench.Bench.row) ->
              if not (Float.is_finite r.trace_s && r.count > 0) then Alcotest.failf "bad row %s" r.kind)
            rows);
    ] )
