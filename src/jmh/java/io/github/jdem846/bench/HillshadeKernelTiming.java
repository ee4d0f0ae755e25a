package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shade.IlluminationStage;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

/**
 * {@link HillshadeBenchmark}'s work (one thread, the seeded fractal, light 320°/25°) in tiles, timed by the thread's
 * CPU time rather than the wall clock, so that other processes on a shared machine disturb it less; prints
 * Mcells/s per round and a hash of every output float (equal hashes = equal floats, e.g. before and after a change
 * of the kernels). Usage: {@code HillshadeKernelTiming SIZE TILE ROUNDS JDEM846|HORN|MULTIDIRECTIONAL}.
 */
public final class HillshadeKernelTiming {

    private HillshadeKernelTiming() {
    }

    public static void main(String[] args) {
        int size = Integer.parseInt(args[0]);
        int tile = Integer.parseInt(args[1]);
        int rounds = Integer.parseInt(args[2]);
        HillshadeMethod method = HillshadeMethod.valueOf(args[3]);
        Dem dem = FractalDem.dem(size, 846L);
        IlluminationStage stage = method.stage(HillshadeOptions.DEFAULTS);
        LightDirection light = new LightDirection(320, 25);
        float[] out = new float[tile * tile];
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        StringBuilder rates = new StringBuilder();
        long hash = 0;
        for (int round = 0; round < rounds; round++) {
            long cpu = 0;
            hash = 0;
            for (int r0 = 0; r0 < size; r0 += tile) {
                for (int c0 = 0; c0 < size; c0 += tile) {
                    int w = Math.min(tile, size - c0);
                    int h = Math.min(tile, size - r0);
                    long t0 = threads.getCurrentThreadCpuTime();
                    stage.illuminate(dem, light, c0, r0, w, h, out);
                    cpu += threads.getCurrentThreadCpuTime() - t0;
                    for (int i = 0; i < w * h; i++) {
                        hash = hash * 31 + Float.floatToRawIntBits(out[i]);
                    }
                }
            }
            rates.append(String.format(" %.1f", (double) size * size / (cpu / 1e3)));
        }
        System.out.println(method + " " + size + "², tiles of " + tile + ", Mcells/s by CPU time:" + rates
                + "; hash " + Long.toHexString(hash));
    }
}
