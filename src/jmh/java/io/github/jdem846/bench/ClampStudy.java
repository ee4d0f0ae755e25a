package io.github.jdem846.bench;

import java.util.Locale;
import java.util.Random;

/**
 * The cost of {@code Math.min}/{@code Math.max} on doubles in a per-cell loop: a bare Horn hillshade over an
 * {@code n × n} float array (no project code), clamped with the {@code Math} forms and with comparisons, a few rounds
 * each in one JVM; its result is in {@code shade.Clamp}'s comment. Usage: {@code ClampStudy [n] [rounds]}.
 */
public final class ClampStudy {

    private ClampStudy() {
    }

    public static void main(String[] args) {
        int n = args.length > 0 ? Integer.parseInt(args[0]) : 2048;
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 10;
        float[] v = new float[n * n];
        Random rnd = new Random(1);
        for (int i = 0; i < v.length; i++) {
            v[i] = (float) (1000 * Math.sin(i * 0.001) + rnd.nextDouble() * 50);
        }
        float[] out = new float[n * n];
        for (int pass = 0; pass < 2; pass++) {
            for (boolean math : new boolean[] {true, false}) {
                StringBuilder times = new StringBuilder();
                for (int r = 0; r < rounds; r++) {
                    long t0 = System.nanoTime();
                    if (math) {
                        hornMath(v, out, n);
                    } else {
                        hornCompare(v, out, n);
                    }
                    times.append(String.format(Locale.ROOT, " %.1f", (System.nanoTime() - t0) / (double) n / n));
                }
                System.out.println((math ? "Math.max/min" : "comparisons ") + " ns per cell:" + times);
            }
        }
    }

    private static void hornMath(float[] v, float[] out, int n) {
        for (int y = 1; y < n - 1; y++) {
            for (int x = 1; x < n - 1; x++) {
                out[y * n + x] = (float) Math.max(-1.0, Math.min(1.0, cosine(v, n, x, y)));
            }
        }
    }

    private static void hornCompare(float[] v, float[] out, int n) {
        for (int y = 1; y < n - 1; y++) {
            for (int x = 1; x < n - 1; x++) {
                double c = cosine(v, n, x, y);
                out[y * n + x] = (float) (c >= 1.0 ? 1.0 : c <= -1.0 ? -1.0 : c);
            }
        }
    }

    /** Horn's cosine of incidence, 30 m cells, light (0.5, 0.5, 0.7). */
    private static double cosine(float[] v, int n, int x, int y) {
        int i = (y - 1) * n + x - 1;
        double w0 = v[i];
        double w1 = v[i + 1];
        double w2 = v[i + 2];
        i += n;
        double w3 = v[i];
        double w5 = v[i + 2];
        i += n;
        double w6 = v[i];
        double w7 = v[i + 1];
        double w8 = v[i + 2];
        double gx = (w2 + 2 * w5 + w8) - (w0 + 2 * w3 + w6);
        double gy = (w0 + 2 * w1 + w2) - (w6 + 2 * w7 + w8);
        double nx = -0.125 * gx * 30;
        double ny = -0.125 * gy * 30;
        double area = 900;
        double len = Math.sqrt(nx * nx + ny * ny + area * area);
        return (nx * 0.5 + ny * 0.5 + area * 0.7) / len;
    }
}
