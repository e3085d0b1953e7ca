#!/usr/bin/env bash
# Makes HABLA's speech evaluation set: what fourteen synthetic teachers, from three speech engines,
# say to the robot, as microphone streams in five acoustic conditions, with the time of every
# utterance. The speech-recognition method is tuned on the voices marked "tune" and reported on the
# voices marked "held-out" only (bench/run speech; docs/methods/speech.md).
#
#   bench/speech/make-eval-set.sh [OUT]            the whole set (default OUT: target/speech-eval), ≈ 2 min
#   bench/speech/make-eval-set.sh --subset OUT     the small part the test suite reads (two held-out
#                                                  voices, one clean, one in pink noise; one take each)
#
# Engines (Debian packages): espeak-ng (formant synthesis, eight accents and voice variants), flite
# (CMU ARCTIC voices awb, rms, slt and the kal diphones: built from recordings of real speakers),
# festival (the kal and ked diphone voices and the ARCTIC slt HTS voice). Needs:
#   apt-get install -y espeak-ng flite festival festvox-kallpc16k festvox-kdlpc16k festvox-us-slt-hts sox
#
# For each voice OUT/<voice>/ holds
#   <condition>.wav   one 16 kHz mono 16-bit stream: every item with 0.7-1.5 s between them, conditions
#                     clean | noise20 (white noise, SNR 20 dB) | noise10 (pink noise, SNR 10 dB) |
#                     echo (a reverberant room) | babble (two other voices talking, SNR 10 dB)
#   labels.tsv        <start s> <end s> <text> <in|oog>: where each item's speech starts and ends
# and OUT/voices.tsv lists <voice> <engine> <split>. Items: the nine phrases of config/grammars/
# commands.gram, each in three takes (normal; faster and higher; slower and lower), and eight words or
# phrases outside the grammar (near misses such as "go", "good", "turn" among them), shuffled.
# Each voice speaks at its own level (peak −3 to −21 dBFS), so normalisation is tested too.
# Everything is deterministic (sox -R, fixed seeds): the same OUT on every run.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
subset=false
if [ "${1:-}" = "--subset" ]; then
  subset=true
  shift
fi
out=${1:-$root/target/speech-eval}

for tool in espeak-ng flite text2wave sox soxi shuf awk; do
  command -v "$tool" >/dev/null || { echo "make-eval-set: $tool is not installed (see the header of $0)" >&2; exit 1; }
done

phrases="go forward
turn left
turn right
go back
stop
good dog
bad dog
well done
no"

# Outside the grammar: near misses of its words first, then other words and phrases a teacher may say.
oog="go
good
turn
dog
left
back
bad
done
go left
turn around
good boy
bad cat
well played
sit down
come here
hello robot
yes
wait
look at me
forward march
fetch the ball
roll over
know
thank you"

# voice : engine : engine's voice name : level (dB below -3 dBFS peak) : split
voices="espeak-us:espeak-ng:en-us:0:tune
espeak-us-f2:espeak-ng:en-us+f2:6:tune
espeak-scotland:espeak-ng:en-gb-scotland:12:tune
flite-kal:flite:kal16:4:tune
flite-awb:flite:awb:9:tune
festival-kal:festival:kal_diphone:2:tune
espeak-caribbean:espeak-ng:en-029:8:held-out
espeak-rp-f3:espeak-ng:en-gb-x-rp+f3:3:held-out
espeak-m3:espeak-ng:en+m3:15:held-out
espeak-lancaster-f4:espeak-ng:en-gb-x-gbclan+f4:10:held-out
flite-rms:flite:rms:5:held-out
flite-slt:flite:slt:11:held-out
festival-ked:festival:ked_diphone:7:held-out
festival-slt-hts:festival:cmu_us_slt_arctic_hts:18:held-out"

# take : espeak words per minute : espeak pitch (0-99) : tempo factor : pitch shift in cents (other engines)
takes="1:160:50:1.0:0
2:195:66:1.2:250
3:135:34:0.85:-250"

conditions="clean noise20 noise10 echo babble"

if $subset; then
  voices=$(echo "$voices" | grep -E '^(flite-slt|espeak-caribbean):')
  takes=$(echo "$takes" | head -1)
  # one stream each: the first voice clean, the second in pink noise
  subset_conditions="espeak-caribbean:clean flite-slt:noise10"
  oog=$(printf 'go\ngood\nturn\nhello robot\n')
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
export LC_ALL=C

# synth <engine> <voice> <text> <take fields...> <file>: 16 kHz mono, silence trimmed both ends
synth() {
  local engine=$1 name=$2 text=$3 wpm=$4 pitch=$5 tempo=$6 cents=$7 file=$8
  case $engine in
    espeak-ng) espeak-ng -v "$name" -s "$wpm" -p "$pitch" -w "$tmp/raw.wav" "$text" ;;
    flite) flite -voice "$name" -t "$text" -o "$tmp/raw.wav" ;;
    festival) echo "$text" | text2wave -eval "(voice_$name)" -o "$tmp/raw.wav" >/dev/null ;;
  esac
  local effects=()
  if [ "$engine" != espeak-ng ]; then
    [ "$tempo" != 1.0 ] && effects+=(tempo -s "$tempo")
    [ "$cents" != 0 ] && effects+=(pitch "$cents")
  fi
  sox -R "$tmp/raw.wav" -r 16000 -c 1 -b 16 -e signed-integer "$file" "${effects[@]}" \
    silence 1 0.01 0.5% reverse silence 1 0.01 0.5% reverse
}

rms_db() { sox "$1" -n stats 2>&1 | awk '/RMS lev dB/ {print $4}'; }

# noise <type> <seconds> <rms dBFS> <file>
noise() {
  sox -R -n -r 16000 -c 1 -b 16 "$tmp/n.wav" synth "$2" "$1" vol 0.5
  local now
  now=$(rms_db "$tmp/n.wav")
  sox -R "$tmp/n.wav" "$4" gain "$(awk -v a="$3" -v b="$now" 'BEGIN {print a - b}')"
}

# The babble: two voices outside the set reading on, for as long as any stream lasts.
babble_text="The weather will be cloudy in the morning with some rain later in the afternoon. \
Please remember to bring the documents to the meeting on Tuesday. I think we should paint the kitchen \
a lighter colour before the summer. The train was late again so I walked the last part of the way."
espeak-ng -v en-us+m7 -s 170 -w "$tmp/b1.wav" "$babble_text $babble_text"
espeak-ng -v en-gb-x-rp+f4 -s 180 -w "$tmp/b2.wav" "$babble_text $babble_text"
sox -R "$tmp/b1.wav" -r 16000 -c 1 "$tmp/b1r.wav"
sox -R "$tmp/b2.wav" -r 16000 -c 1 "$tmp/b2r.wav" pad 1.3 0
sox -R -m "$tmp/b1r.wav" "$tmp/b2r.wav" "$tmp/babble1.wav"
sox -R "$tmp/babble1.wav" "$tmp/babble1.wav" "$tmp/babble1.wav" "$tmp/babble.wav"

: > "$out/voices.tsv"
seed=0
echo "$voices" | while IFS=: read -r voice engine name level split; do
  seed=$((seed + 1))
  dir="$out/$voice"
  rm -rf "$dir"
  mkdir -p "$dir" "$tmp/items"
  rm -f "$tmp/items/"*
  n=0
  # the items: every phrase in every take, and this voice's share of the out-of-grammar list
  while IFS=: read -r take wpm pitch tempo cents; do
    while IFS= read -r phrase; do
      n=$((n + 1))
      synth "$engine" "$name" "$phrase" "$wpm" "$pitch" "$tempo" "$cents" "$tmp/items/$n.wav"
      printf '%s\t%s\tin\n' "$n" "$phrase" >> "$tmp/items.tsv.$voice"
    done <<< "$phrases"
  done <<< "$takes"
  count=$(echo "$oog" | wc -l)
  per=8
  $subset && per=$count
  for k in $(seq 0 $((per - 1))); do
    line=$(( (seed * 5 + k * 3) % count + 1 ))
    $subset && line=$((k + 1))
    word=$(echo "$oog" | sed -n "${line}p")
    t=$(( k % $(echo "$takes" | wc -l) + 1 ))
    IFS=: read -r _ wpm pitch tempo cents <<< "$(echo "$takes" | sed -n "${t}p")"
    n=$((n + 1))
    synth "$engine" "$name" "$word" "$wpm" "$pitch" "$tempo" "$cents" "$tmp/items/$n.wav"
    printf '%s\t%s\toog\n' "$n" "$word" >> "$tmp/items.tsv.$voice"
  done
  # each voice at its own level
  for f in "$tmp/items/"*.wav; do
    sox -R "$f" "$f.lv.wav" gain -n "-$((3 + level))"
    mv "$f.lv.wav" "$f"
  done
  # the clean stream: shuffled items with 0.7-1.5 s of digital silence before each, 1 s after the last
  shuf --random-source=<(yes "$voice") "$tmp/items.tsv.$voice" > "$tmp/order.tsv"
  parts=()
  at=0
  : > "$dir/labels.tsv"
  i=0
  while IFS=$'\t' read -r item text kind; do
    i=$((i + 1))
    gap=$(awk -v s="$seed" -v i="$i" 'BEGIN {srand(s * 1000 + i); printf "%.2f", 0.7 + rand() * 0.8}')
    sox -n -r 16000 -c 1 -b 16 "$tmp/gap$i.wav" trim 0 "$gap"
    len=$(soxi -D "$tmp/items/$item.wav")
    start=$(awk -v a="$at" -v g="$gap" 'BEGIN {printf "%.4f", a + g}')
    end=$(awk -v s="$start" -v l="$len" 'BEGIN {printf "%.4f", s + l}')
    printf '%s\t%s\t%s\t%s\n' "$start" "$end" "$text" "$kind" >> "$dir/labels.tsv"
    at=$end
    parts+=("$tmp/gap$i.wav" "$tmp/items/$item.wav")
  done < "$tmp/order.tsv"
  sox -n -r 16000 -c 1 -b 16 "$tmp/tail.wav" trim 0 1
  sox "${parts[@]}" "$tmp/tail.wav" "$tmp/clean.wav"
  # the speech's own level, measured over the items alone, sets the noise levels (SNR)
  sox "$tmp/items/"*.wav "$tmp/speech.wav"
  speech=$(rms_db "$tmp/speech.wav")
  total=$(soxi -D "$tmp/clean.wav")
  $subset && conditions=$(echo "$subset_conditions" | tr ' ' '\n' | sed -n "s/^$voice://p")
  for c in $conditions; do
    case $c in
      clean) cp "$tmp/clean.wav" "$dir/clean.wav" ;;
      noise20)
        noise whitenoise "$total" "$(awk -v s="$speech" 'BEGIN {print s - 20}')" "$tmp/noise.wav"
        sox -R -m -v 1 "$tmp/clean.wav" -v 1 "$tmp/noise.wav" "$dir/noise20.wav" ;;
      noise10)
        noise pinknoise "$total" "$(awk -v s="$speech" 'BEGIN {print s - 10}')" "$tmp/noise.wav"
        sox -R -m -v 1 "$tmp/clean.wav" -v 1 "$tmp/noise.wav" "$dir/noise10.wav" ;;
      echo)
        # reverberance 60 %, HF damping 50 %, a large room; the dry sound kept, the tail cut at the stream's end
        sox -R "$tmp/clean.wav" "$dir/echo.wav" reverb 60 50 90 100 0 0 trim 0 "$total" ;;
      babble)
        sox -R "$tmp/babble.wav" "$tmp/bab.wav" trim "$(awk -v s="$seed" 'BEGIN {print s * 1.7}')" "$total"
        now=$(rms_db "$tmp/bab.wav")
        sox -R "$tmp/bab.wav" "$tmp/bab2.wav" gain "$(awk -v s="$speech" -v b="$now" 'BEGIN {print s - 10 - b}')"
        sox -R -m -v 1 "$tmp/clean.wav" -v 1 "$tmp/bab2.wav" "$dir/babble.wav" ;;
    esac
  done
  printf '%s\t%s\t%s\n' "$voice" "$engine" "$split" >> "$out/voices.tsv"
  echo "make-eval-set: $voice ($engine $name, $split): $(wc -l < "$dir/labels.tsv") items, ${total%.*} s per condition"
done
echo "make-eval-set: wrote $(wc -l < "$out/voices.tsv") voices to $out"
