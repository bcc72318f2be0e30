(** How far apart two 8-bit images are: the measures the cross-renders
    with POV-Ray are judged by, and pictures of the differences. The
    functions taking two images raise [Invalid_argument] when their sizes
    differ. *)

val psnr : Image.rgb8 -> Image.rgb8 -> float
(** PSNR in dB over the R, G, B bytes; [infinity] for identical images.
    Requires equal sizes. *)

val ssim : Image.rgb8 -> Image.rgb8 -> float
(** Mean SSIM on the luma Y = 0.2126 R + 0.7152 G + 0.0722 B of the 8-bit
    values, Gaussian window 11x11 with sigma 1.5, K1 = 0.01, K2 = 0.03,
    L = 255, averaged over the windows that fit inside the image (as
    scikit-image's [structural_similarity] with [gaussian_weights=True],
    [use_sample_covariance=False], [data_range=255]). Requires equal sizes
    of at least 11x11. *)

val max_diff : Image.rgb8 -> Image.rgb8 -> int
(** Largest absolute difference of any channel. *)

val diff_image : ?gain:int -> Image.rgb8 -> Image.rgb8 -> Image.rgb8
(** Per-channel absolute difference times [gain] (default 4), clipped. *)

val side_by_side : Image.rgb8 list -> Image.rgb8
(** The images placed left to right (heights padded with black). *)
