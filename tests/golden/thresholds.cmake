# The golden thresholds, in one place: a povwall render matches POV-Ray's when
#   rmse <= GOLDEN_MAX_RMSE and the fraction of pixels with any channel off by more than
#   GOLDEN_BAD_CHANNEL (0..1 scale) is <= GOLDEN_MAX_BAD_FRACTION.
set(GOLDEN_MAX_RMSE 0.01)
set(GOLDEN_BAD_CHANNEL 0.1)
set(GOLDEN_MAX_BAD_FRACTION 0.002)
# Image sizes: small, so the suite takes a few minutes on 2 cores.
set(GOLDEN_SIZE -W 160 -H 120)
set(GOLDEN_DEMO_SIZE -W 120 -H 120)
# The sanitizer build renders the golden scenes with povwall alone, smaller, looking for
# memory errors and undefined behaviour; the release suite compares them with POV-Ray.
# (Under ASan they took a third of CI's sanitizer run.)
set(GOLDEN_OURS_ONLY "")
if(POVWALL_SANITIZE)
  set(GOLDEN_SIZE -W 64 -H 48)
  set(GOLDEN_DEMO_SIZE -W 48 -H 48)
  set(GOLDEN_OURS_ONLY --ours-only)
endif()
