#!/usr/bin/python3
"""Draws one exported episode's audio (export_dataset or run_episodes --audio, docs/audio.md):
the waveform of a raw microphone above its spectrogram, with the speaker turns of its RTTM file
as coloured bars and names, to look at what a data set holds.

usage: draw_audio.py STEM OUT.png [--channel C] [--from S] [--to S]

STEM is the episode's files without their endings (DIR/audio/NAME_SEED); channel C of STEM.wav
(default 1, a raw microphone, which hears ARI too) from S to S seconds (default: all). Needs sox
(the spectrogram), ImageMagick (the drawing) and the DejaVu fonts, as scripts/install_deps.sh
installs them."""
import argparse
import os
import subprocess
import sys
import tempfile
import wave

import numpy

WIDTH, WAVE_HEIGHT, SPECTRUM_HEIGHT, TURN_HEIGHT, MARGIN = 1200, 160, 300, 28, 60
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"  # fonts-dejavu-core
COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"]


def read_channel(path, channel, start_s, end_s):
    with wave.open(path) as w:
        if not 0 <= channel < w.getnchannels():
            sys.exit("draw_audio: --channel: expected 0..%d, got %d" % (w.getnchannels() - 1, channel))
        rate = w.getframerate()
        samples = numpy.frombuffer(w.readframes(w.getnframes()), dtype="<i2")
        samples = samples.reshape(-1, w.getnchannels())[:, channel] / 32768.0
    end_s = len(samples) / rate if end_s is None else end_s
    return samples[int(start_s * rate):int(end_s * rate)], rate, end_s


def turns(path, start_s, end_s):
    found = []
    for line in open(path):
        fields = line.split()
        begin, length, speaker = float(fields[3]), float(fields[4]), fields[7]
        if begin < end_s and begin + length > start_s:
            found.append((max(begin, start_s), min(begin + length, end_s), speaker))
    return found


def waveform_commands(samples, top):
    """Per pixel column, a line from the column's lowest to its highest sample."""
    columns = numpy.array_split(samples, WIDTH)
    middle = top + WAVE_HEIGHT / 2
    lines = ["stroke #333333"]
    for x, column in enumerate(columns):
        low, high = (column.min(), column.max()) if len(column) else (0.0, 0.0)
        lines.append("line %d,%.1f %d,%.1f" % (MARGIN + x, middle - high * WAVE_HEIGHT / 2,
                                                MARGIN + x, middle - low * WAVE_HEIGHT / 2))
    return lines


def turn_commands(found, start_s, end_s, top):
    speakers = sorted({speaker for _, _, speaker in found})
    scale = WIDTH / (end_s - start_s)
    lines = ["stroke none", "font '%s'" % FONT, "font-size 14"]
    for begin, end, speaker in found:
        colour = COLOURS[speakers.index(speaker) % len(COLOURS)]
        x0, x1 = MARGIN + (begin - start_s) * scale, MARGIN + (end - start_s) * scale
        lines += ["fill %s" % colour, "rectangle %.1f,%d %.1f,%d" % (x0, top, x1, top + TURN_HEIGHT),
                  "fill white", "text %.1f,%d '%s'" % (x0 + 3, top + 19, speaker)]
    return lines


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("stem")
    parser.add_argument("out")
    parser.add_argument("--channel", type=int, default=1)
    parser.add_argument("--from", dest="start_s", type=float, default=0.0)
    parser.add_argument("--to", dest="end_s", type=float, default=None)
    args = parser.parse_args()
    for ending in (".wav", ".rttm"):
        if not os.path.isfile(args.stem + ending):
            sys.exit("draw_audio: %s%s: no such file (STEM is DIR/audio/NAME_SEED)" % (args.stem, ending))
    samples, rate, end_s = read_channel(args.stem + ".wav", args.channel, args.start_s, args.end_s)
    if end_s <= args.start_s:
        sys.exit("draw_audio: --to: expected a time after --from (%.2f s), got %.2f" % (args.start_s, end_s))
    with tempfile.TemporaryDirectory() as folder:
        spectrum = os.path.join(folder, "spectrum.png")
        subprocess.run(["sox", args.stem + ".wav", "-n", "remix", str(args.channel + 1),
                        "trim", str(args.start_s), str(end_s - args.start_s), "spectrogram",
                        "-x", str(WIDTH), "-y", str(SPECTRUM_HEIGHT), "-r", "-o", spectrum],
                       check=True)
        turn_top = MARGIN + WAVE_HEIGHT + 10
        spectrum_top = turn_top + TURN_HEIGHT + 10
        # ImageMagick's default policy refuses drawing files: the commands go as one argument.
        draw = "\n".join(
                waveform_commands(samples, MARGIN) +
                turn_commands(turns(args.stem + ".rttm", args.start_s, end_s), args.start_s, end_s,
                              turn_top) +
                ["fill black", "font '%s'" % FONT, "font-size 16",
                 "text %d,30 '%s, channel %d: waveform, speaker turns (RTTM), spectrogram 0-8 kHz'"
                 % (MARGIN, os.path.basename(args.stem), args.channel),
                 "font-size 13",
                 "text %d,%d '%.1f s'" % (MARGIN, spectrum_top + SPECTRUM_HEIGHT + 20, args.start_s),
                 "text %d,%d '%.1f s'" % (MARGIN + WIDTH - 40, spectrum_top + SPECTRUM_HEIGHT + 20,
                                          end_s)])
        height = spectrum_top + SPECTRUM_HEIGHT + 30
        subprocess.run(["convert", "-size", "%dx%d" % (WIDTH + 2 * MARGIN, height), "xc:white",
                        spectrum, "-geometry", "+%d+%d" % (MARGIN, spectrum_top), "-composite",
                        "-draw", draw, args.out], check=True)
    print("draw_audio: %s" % args.out)


if __name__ == "__main__":
    main()
