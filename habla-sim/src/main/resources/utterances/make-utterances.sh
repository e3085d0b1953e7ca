#!/bin/sh
# Makes the teacher's spoken commands and rewards for the simulated Aibo: every phrase of the
# HABLA vocabulary, in two synthetic voices, four takes each with a different speaking rate and
# pitch, as 16 kHz mono 16-bit WAV files, plus index.txt ("<voice>/<file><TAB><phrase>").
#
# Needs espeak-ng and sox (Debian/Ubuntu: apt-get install -y espeak-ng sox).
# Run from anywhere; it writes next to itself and replaces what was there.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
cd "$here"

phrases="go forward
turn left
turn right
go back
stop
good dog
bad dog
well done
no"

# voice directory : espeak-ng voice
voices="en-us-male:en-us en-us-female:en-us+f2"

# take : words per minute : pitch (0-99)
takes="1:150:45 2:170:55 3:135:38 4:185:62"

command -v espeak-ng >/dev/null || { echo "espeak-ng is not installed" >&2; exit 1; }
command -v sox >/dev/null || { echo "sox is not installed" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

: > index.txt
for pair in $voices; do
  dir=${pair%%:*}
  voice=${pair#*:}
  rm -rf "$dir"
  mkdir -p "$dir"
  echo "$phrases" | while IFS= read -r phrase; do
    stem=$(echo "$phrase" | tr ' ' '_')
    for take in $takes; do
      n=${take%%:*}
      rest=${take#*:}
      wpm=${rest%%:*}
      pitch=${rest#*:}
      file="${stem}_${n}.wav"
      espeak-ng -v "$voice" -s "$wpm" -p "$pitch" -w "$tmp/raw.wav" "$phrase"
      # 16 kHz mono 16-bit; trim the synthesiser's silence, then keep 150 ms of quiet either side
      sox "$tmp/raw.wav" -r 16000 -c 1 -b 16 -e signed-integer "$dir/$file" \
        silence 1 0.01 0.5% reverse silence 1 0.01 0.5% reverse pad 0.15 0.15
      printf '%s/%s\t%s\n' "$dir" "$file" "$phrase" >> index.txt
    done
  done
done
echo "wrote $(wc -l < index.txt) utterances to $here"
