# Sourced by the rate benches (rate_bench.sh, rate_sweep.sh, rate_templates.sh) as
# `source bench/tools/rate_images.sh DIR`: the images they paint. Sets STILLS (foreign/coffee-256.png,
# then stills/*), FRAMES (frame 30 of each clip in video/ at 1280x720, written into DIR) and
# IMAGES (both); MEDIA names the shared media folder.
STILLS=("$MEDIA"/foreign/coffee-256.png "$MEDIA"/stills/*)
FRAMES=()
for _clip in "$MEDIA"/video/*; do
  ffmpeg -loglevel error -y -i "$_clip" -vf "select=eq(n\,30),scale=1280:720" -frames:v 1 "$1/$(basename "$_clip")-720.png"
  FRAMES+=("$1/$(basename "$_clip")-720.png")
done
IMAGES=("${STILLS[@]}" "${FRAMES[@]}")
