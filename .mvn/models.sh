# The speech models HABLA runs but never keeps in its repository (docs/methods/speech.md, "The Moonshine model").
# Sourced by the launcher (bash); defines
#   habla_models_folder          prints the cache folder of the Moonshine model
#   habla_models_fetch ROOT      fetches it, if the folder lacks a file or a file differs from its pinned sum
#   habla_models_present ROOT    true when the folder holds every pinned file (the daemon checks their sums)
#   habla_models_needed ARGS...  true when one of ARGS is a config file whose speech-recognition names moonshine
#
# The model is Moonshine base-en (MIT licence): its ONNX Runtime files (encoder_model.ort, decoder_model_merged.ort)
# and LICENSE come in the PyPI wheel moonshine-cpp 0.1.4, its tokenizer.json in useful-moonshine-onnx 20251121.
# pip downloads both wheels (their own SHA-256 sums pinned below, so pip refuses any other file), the files are
# extracted into a temporary folder, .mvn/moonshine_convert.py (Python's standard library only) turns the two
# ONNX Runtime files into the ONNX models HABLA runs (encoder.onnx, decoder.onnx: the same network with its 8-bit
# weights kept in 8 bits), the results are checked against the sums in ROOT/habla-methods/src/main/resources/org/
# habla/methods/speech/moonshine-base-en.sha256 (the same sums the daemon checks when it loads the model), and only
# then moved into the cache folder. A lab without a network copies that folder from a machine that fetched it.

HABLA_MOONSHINE_WHEELS='moonshine-cpp==0.1.4 --hash=sha256:f7afc662bdd3ef98815ee3b940438b456e77d5a77cea5396ed9c572785412ebd
useful-moonshine-onnx==20251121 --hash=sha256:b4189b0d7dc8064d567fd0b5d5ce78634be290b0a3a3274ab80ad11c46d531a2'

habla_models_folder() {
  if [ -n "${HABLA_MODELS:-}" ]; then
    printf '%s\n' "$HABLA_MODELS/moonshine-base-en"
  else
    printf '%s\n' "${XDG_CACHE_HOME:-$HOME/.cache}/habla/models/moonshine-base-en"
  fi
}

_habla_models_sums() {
  printf '%s\n' "$1/habla-methods/src/main/resources/org/habla/methods/speech/moonshine-base-en.sha256"
}

# True when every pinned file is in FOLDER with its pinned sum.
_habla_models_whole() {
  [ -d "$2" ] && (cd "$2" && grep -v '^#' "$(_habla_models_sums "$1")" | sha256sum -c --status - 2>/dev/null)
}

habla_models_fetch() {
  _root=$1
  _folder=$(habla_models_folder)
  if _habla_models_whole "$_root" "$_folder"; then
    echo "habla: the Moonshine model is in $_folder (every file matches its pinned SHA-256)" >&2
    return 0
  fi
  command -v python3 >/dev/null || { echo "habla: python3 (with pip) is needed to fetch the Moonshine model" >&2; return 1; }
  echo "habla: fetching the Moonshine model (PyPI wheels moonshine-cpp 0.1.4 and useful-moonshine-onnx 20251121, 55 MB) into $_folder ..." >&2
  _tmp=$(mktemp -d)
  trap 'rm -rf "$_tmp"' RETURN
  printf '%s\n' "$HABLA_MOONSHINE_WHEELS" > "$_tmp/wheels.txt"
  if ! python3 -m pip download --quiet --no-deps --only-binary=:all: --require-hashes -r "$_tmp/wheels.txt" \
      -d "$_tmp/wheels" >&2; then
    echo "habla: pip could not download the Moonshine wheels; on a machine without a network, copy the folder" \
         "$_folder from one that has it" >&2
    return 1
  fi
  mkdir -p "$_tmp/model"
  python3 - "$_tmp/wheels" "$_tmp/model" <<'PY' || return 1
import pathlib, sys, zipfile
wheels, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
wanted = {
    "moonshine_cpp-0.1.4.data/purelib/moonshine_cpp/models/base-en/encoder_model.ort": "encoder_model.ort",
    "moonshine_cpp-0.1.4.data/purelib/moonshine_cpp/models/base-en/decoder_model_merged.ort": "decoder_model_merged.ort",
    "moonshine_cpp-0.1.4.data/purelib/moonshine_cpp/LICENSE": "LICENSE",
    "moonshine_onnx/assets/tokenizer.json": "tokenizer.json",
}
for wheel in wheels.glob("*.whl"):
    with zipfile.ZipFile(wheel) as z:
        for name in z.namelist():
            if name in wanted:
                (out / wanted.pop(name)).write_bytes(z.read(name))
if wanted:
    sys.exit("habla: the wheels lack " + ", ".join(sorted(wanted)))
PY
  python3 "$_root/.mvn/moonshine_convert.py" "$_tmp/model/encoder_model.ort" "$_tmp/model/decoder_model_merged.ort" \
    "$_tmp/model" || return 1
  rm -f "$_tmp/model/encoder_model.ort" "$_tmp/model/decoder_model_merged.ort"
  if ! _habla_models_whole "$_root" "$_tmp/model"; then
    echo "habla: the extracted Moonshine files do not match their pinned SHA-256 sums; nothing was installed" >&2
    return 1
  fi
  mkdir -p "$_folder"
  for _f in "$_tmp/model"/*; do
    mv -f "$_f" "$_folder/"
  done
  # the wheel's own files, kept there by HABLA before it converted them
  rm -f "$_folder/encoder_model.ort" "$_folder/decoder_model_merged.ort"
  echo "habla: the Moonshine model is in $_folder (every file matches its pinned SHA-256)" >&2
}

# True when every pinned file is in the cache folder (their sums are checked by the daemon when it loads them).
habla_models_present() {
  _folder=$(habla_models_folder)
  for _f in $(grep -v '^#' "$(_habla_models_sums "$1")" | awk '{print $2}'); do
    [ -f "$_folder/$_f" ] || return 1
  done
}

habla_models_needed() {
  for _arg in "$@"; do
    case "$_arg" in
      *.json)
        [ -f "$_arg" ] && grep -Eq '"engine"[[:space:]]*:[[:space:]]*"moonshine"' "$_arg" && return 0 ;;
    esac
  done
  return 1
}
