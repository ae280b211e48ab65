#!/usr/bin/env python3
"""Draws search time against graph size from results/search_sweep.csv as an SVG (log-log, no
dependencies beyond the standard library). Usage: plot_sweep.py [CSV] [SVG]."""

import csv
import math
import sys


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else "results/search_sweep.csv"
    target = sys.argv[2] if len(sys.argv) > 2 else "results/search_sweep.svg"
    with open(source) as handle:
        rows = list(csv.DictReader(line for line in handle if not line.startswith("#")))
    points = [(float(r["vertices"]), float(r["cpu_median_us"]), float(r["cpu_p99_us"])) for r in rows]
    width, height, margin = 640, 420, 60
    x_low, x_high = math.log10(50), math.log10(50000)
    y_low, y_high = math.log10(1), math.log10(10000)

    def x_of(value):
        return margin + (math.log10(value) - x_low) / (x_high - x_low) * (width - 2 * margin)

    def y_of(value):
        return height - margin - (math.log10(value) - y_low) / (y_high - y_low) * (height - 2 * margin)

    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" font-size="12">',
             f'<rect width="{width}" height="{height}" fill="white"/>',
             f'<text x="{width / 2}" y="20" text-anchor="middle">Global search (attach + A*) vs graph size, thread CPU time</text>']
    for exponent in range(2, 5):
        x = x_of(10 ** exponent)
        parts.append(f'<line x1="{x}" y1="{margin}" x2="{x}" y2="{height - margin}" stroke="#ddd"/>')
        parts.append(f'<text x="{x}" y="{height - margin + 16}" text-anchor="middle">{10 ** exponent}</text>')
    for exponent in range(0, 5):
        y = y_of(10 ** exponent)
        parts.append(f'<line x1="{margin}" y1="{y}" x2="{width - margin}" y2="{y}" stroke="#ddd"/>')
        parts.append(f'<text x="{margin - 6}" y="{y + 4}" text-anchor="end">{10 ** exponent}</text>')
    parts.append(f'<text x="{width / 2}" y="{height - 15}" text-anchor="middle">vertices</text>')
    parts.append(f'<text x="15" y="{height / 2}" transform="rotate(-90 15 {height / 2})" text-anchor="middle">microseconds</text>')
    for index, colour, label in ((1, "#1f77b4", "median"), (2, "#d62728", "p99")):
        path = " ".join(f"{x_of(p[0]):.1f},{y_of(p[index]):.1f}" for p in points)
        parts.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for p in points:
            parts.append(f'<circle cx="{x_of(p[0]):.1f}" cy="{y_of(p[index]):.1f}" r="3" fill="{colour}"/>')
        parts.append(f'<text x="{margin + 10}" y="{margin + 14 * index}" fill="{colour}">{label}</text>')
    parts.append("</svg>")
    with open(target, "w") as handle:
        handle.write("\n".join(parts) + "\n")


if __name__ == "__main__":
    main()
