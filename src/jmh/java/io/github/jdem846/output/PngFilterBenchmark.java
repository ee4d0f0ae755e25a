package io.github.jdem846.output;

import io.github.jdem846.testing.SyntheticDems;
import io.github.jdem846.testing.SyntheticDems.ShadedRelief;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.io.File;
import java.io.IOException;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * PNG row filtering (choosing each row's filter and writing it) of one deflate segment, about 1 MiB of rows 4000
 * pixels wide: {@link PngRowFilter} ({@code words}) against the byte-at-a-time loop it replaced ({@code bytes},
 * kept below as it was, the branching Paeth predictor included). Pictures: the seeded fractal's hillshade
 * ({@code gray}), its tinted relief ({@code rgba}), a two-value mask made from the hillshade ({@code mask}); or,
 * with {@code -p file=PATH}, the first rows of a PNG (gray or RGBA), e.g. a hillshade of a rough DEM, where the
 * branches of the old Paeth predictor mispredict more. Microseconds per segment (docs/performance.md, "Writing PNG
 * and GeoTIFF").
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class PngFilterBenchmark {

    private static final int WIDTH = 4000;

    @Param({"gray", "rgba", "mask"})
    String picture;

    @Param({"words", "bytes"})
    String filter;

    /** A PNG to take the rows from instead of {@link #picture}; empty for the synthetic pictures. */
    @Param("")
    String file;

    private byte[][] rows;
    private byte[] out;
    private RowFilter rowFilter;

    private interface RowFilter {
        int filterRow(byte[] row, byte[] above, byte[] out, int off);
    }

    @Setup
    public void setUp() throws IOException {
        int bpp;
        int width;
        byte[] samples;
        if (!file.isEmpty()) {
            BufferedImage image = ImageIO.read(new File(file));
            width = image.getWidth();
            boolean gray = image.getType() == BufferedImage.TYPE_BYTE_GRAY;
            bpp = gray ? 1 : 4;
            samples = gray ? ((DataBufferByte) image.getRaster().getDataBuffer()).getData()
                    : rgba(image.getRGB(0, 0, width, image.getHeight(), null, 0, width));
        } else {
            bpp = picture.equals("rgba") ? 4 : 1;
            width = WIDTH;
            ShadedRelief relief = SyntheticDems.shadedRelief(WIDTH, PngWriter.SEGMENT_BYTES / WIDTH, 846);
            samples = switch (picture) {
                case "gray" -> relief.gray();
                case "rgba" -> rgba(relief.argb());
                default -> mask(relief.gray());
            };
        }
        int rowBytes = width * bpp;
        int n = Math.min(samples.length / rowBytes, Math.max(1, PngWriter.SEGMENT_BYTES / (rowBytes + 1)));
        rows = new byte[n + 1][1 + rowBytes];
        for (int r = 0; r < n; r++) {
            System.arraycopy(samples, r * rowBytes, rows[r + 1], 1, rowBytes);
        }
        out = new byte[n * (1 + rowBytes)];
        rowFilter = filter.equals("words") ? new PngRowFilter(rowBytes, bpp)::filterRow
                : new ByteWise(rowBytes, bpp)::filterRow;
    }

    /** Filters the segment's rows (the first under a row of zeros, as at the top of a picture). */
    @Benchmark
    public byte[] filterSegment() {
        int n = rows[0].length;
        for (int r = 1; r < rows.length; r++) {
            rowFilter.filterRow(rows[r], rows[r - 1], out, (r - 1) * n);
        }
        return out;
    }

    private static byte[] rgba(int[] argb) {
        byte[] b = new byte[argb.length * 4];
        for (int i = 0; i < argb.length; i++) {
            b[4 * i] = (byte) (argb[i] >> 16);
            b[4 * i + 1] = (byte) (argb[i] >> 8);
            b[4 * i + 2] = (byte) argb[i];
            b[4 * i + 3] = (byte) (argb[i] >>> 24);
        }
        return b;
    }

    /** 255 where the hillshade is darker than 100 (in shadow), 0 elsewhere. */
    private static byte[] mask(byte[] gray) {
        byte[] m = new byte[gray.length];
        for (int i = 0; i < gray.length; i++) {
            m[i] = (byte) ((gray[i] & 0xFF) < 100 ? 255 : 0);
        }
        return m;
    }

    /** The filter before {@link PngRowFilter}: one byte at a time, the five sums in one pass. */
    private static final class ByteWise {
        private final int bpp;
        private final byte[] paeth;

        ByteWise(int sampleBytes, int bytesPerPixel) {
            bpp = bytesPerPixel;
            paeth = new byte[1 + sampleBytes];
        }

        int filterRow(byte[] c, byte[] p, byte[] out, int off) {
            int type = choose(c, p);
            apply(type, c, p, out, off);
            return type;
        }

        private int choose(byte[] c, byte[] p) {
            byte[] t = paeth;
            long sumNone = 0;
            long sumSub = 1;
            long sumUp = 2;
            long sumAvg = 3;
            long sumPaeth = 4;
            int n = c.length;
            int head = Math.min(n, 1 + bpp);
            for (int i = 1; i < head; i++) {
                int x = c[i] & 0xFF;
                int b = p[i] & 0xFF;
                sumNone += x;
                sumSub += Math.abs((byte) x);
                sumUp += Math.abs((byte) (x - b));
                sumAvg += Math.abs((byte) (x - (b >> 1)));
                t[i] = (byte) (x - b);
                sumPaeth += Math.abs(t[i]);
            }
            for (int i = head; i < n; i++) {
                int x = c[i] & 0xFF;
                int b = p[i] & 0xFF;
                int a = c[i - bpp] & 0xFF;
                int d = p[i - bpp] & 0xFF;
                sumNone += x;
                sumSub += Math.abs((byte) (x - a));
                sumUp += Math.abs((byte) (x - b));
                sumAvg += Math.abs((byte) (x - ((a + b) >> 1)));
                byte e = (byte) (x - PngRowFilter.paeth(a, b, d));
                t[i] = e;
                sumPaeth += Math.abs(e);
            }
            int best = 0;
            long min = sumNone;
            if (min > sumSub) {
                best = 1;
                min = sumSub;
            }
            if (min > sumUp) {
                best = 2;
                min = sumUp;
            }
            if (min > sumAvg) {
                best = 3;
                min = sumAvg;
            }
            if (min > sumPaeth) {
                best = 4;
            }
            return best;
        }

        private void apply(int type, byte[] c, byte[] p, byte[] out, int off) {
            int n = c.length;
            out[off] = (byte) type;
            int head = Math.min(n, 1 + bpp);
            switch (type) {
                case 0 -> System.arraycopy(c, 1, out, off + 1, n - 1);
                case 1 -> {
                    System.arraycopy(c, 1, out, off + 1, head - 1);
                    for (int i = head; i < n; i++) {
                        out[off + i] = (byte) (c[i] - c[i - bpp]);
                    }
                }
                case 2 -> {
                    for (int i = 1; i < n; i++) {
                        out[off + i] = (byte) (c[i] - p[i]);
                    }
                }
                case 3 -> {
                    for (int i = 1; i < head; i++) {
                        out[off + i] = (byte) (c[i] - ((p[i] & 0xFF) >> 1));
                    }
                    for (int i = head; i < n; i++) {
                        out[off + i] = (byte) (c[i] - (((c[i - bpp] & 0xFF) + (p[i] & 0xFF)) >> 1));
                    }
                }
                default -> System.arraycopy(paeth, 1, out, off + 1, n - 1);
            }
        }
    }
}
