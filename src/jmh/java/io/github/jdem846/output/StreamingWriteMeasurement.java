package io.github.jdem846.output;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes one synthetic gray picture (a smooth relief with fine noise and a no-data corner, computed row by row) as
 * a PNG, a stripped GeoTIFF or a COG, either whole ({@link ImageOutput#writeGray} of one array) or streamed in
 * bands ({@link ImageOutput#openGray}), and prints the time spent writing (the picture's computation excluded), the
 * file size and the peak heap (the sum of the heap pools' peaks, an upper bound). Run each case in its own JVM:
 *
 * <pre>
 * ./mvnw -Pjmh package -DskipTests
 * java -Xmx1g -cp target/benchmarks.jar io.github.jdem846.output.StreamingWriteMeasurement whole cog 20000 512 out
 * java -Xmx64m -cp target/benchmarks.jar io.github.jdem846.output.StreamingWriteMeasurement stream cog 20000 512 out
 * </pre>
 *
 * Arguments: {@code whole|stream}, {@code png|tif|cog}, the picture's edge in pixels, rows per band, a directory.
 */
public final class StreamingWriteMeasurement {

    private StreamingWriteMeasurement() {
    }

    public static void main(String[] args) throws Exception {
        boolean whole = args[0].equals("whole");
        String format = args[1];
        int size = Integer.parseInt(args[2]);
        int bandRows = Integer.parseInt(args[3]);
        Path dir = Files.createDirectories(Path.of(args[4]));
        Path file = dir.resolve(args[0] + "." + (format.equals("png") ? "png" : format.equals("cog") ? "cog.tif"
                : "tif"));
        WriteOptions options = WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.NONE).withNoData(0);
        if (format.equals("cog")) {
            options = options.withTiffLayout(WriteOptions.TiffLayout.COG);
        }
        Picture picture = new Picture(size);
        long nanos;
        if (whole) {
            byte[] gray = new byte[Math.multiplyExact(size, size)];
            for (int y = 0; y < size; y += bandRows) {
                picture.rows(y, Math.min(bandRows, size - y), gray, y * size);
            }
            long t0 = System.nanoTime();
            ImageOutput.writeGray(file, gray, size, size, null, options);
            nanos = System.nanoTime() - t0;
        } else {
            byte[] band = new byte[Math.multiplyExact(size, bandRows)];
            nanos = 0;
            try (ImageSink sink = ImageOutput.openGray(file, size, size, null, options)) {
                for (int y = 0; y < size; y += bandRows) {
                    int rows = Math.min(bandRows, size - y);
                    picture.rows(y, rows, band, 0);
                    long t0 = System.nanoTime();
                    sink.appendGray(band, rows);
                    nanos += System.nanoTime() - t0;
                }
                long t0 = System.nanoTime();
                sink.commit();
                nanos += System.nanoTime() - t0;
            }
        }
        long peak = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                peak += pool.getPeakUsage().getUsed();
            }
        }
        double megapixels = (double) size * size / 1e6;
        System.out.printf(Locale.ROOT, "%s %s %d² bands of %d: %.1f s, %.0f Mpx/s, file %.1f MB, peak heap %.0f MB,"
                        + " -Xmx %.0f MB%n", args[0], format, size, bandRows, nanos / 1e9, megapixels / (nanos / 1e9),
                Files.size(file) / 1e6, peak / 1e6, Runtime.getRuntime().maxMemory() / 1e6);
    }

    /** The picture: computed from per-column and per-row waves and a hash, so never held whole unless asked. */
    private static final class Picture {
        private final int size;
        private final float[] across;
        private final float[] down;

        Picture(int size) {
            this.size = size;
            this.across = new float[size];
            this.down = new float[size];
            for (int i = 0; i < size; i++) {
                across[i] = (float) (60 * Math.sin(i * 0.0021) + 25 * Math.sin(i * 0.017 + 1));
                down[i] = (float) (50 * Math.cos(i * 0.0013) + 20 * Math.sin(i * 0.023));
            }
        }

        /** Rows {@code [y0, y0 + rows)} into {@code dst} from {@code offset}. */
        void rows(int y0, int rows, byte[] dst, int offset) {
            for (int r = 0; r < rows; r++) {
                int y = y0 + r;
                int at = offset + r * size;
                for (int x = 0; x < size; x++) {
                    if (x + y < size / 8) {
                        dst[at + x] = 0;                                        // no-data corner
                        continue;
                    }
                    int h = x * 0x9E3779B1 ^ y * 0x85EBCA77;
                    h ^= h >>> 15;
                    int v = 128 + (int) (across[x] + down[y]) + ((h & 7) - 3);
                    dst[at + x] = (byte) Math.max(1, Math.min(255, v));
                }
            }
        }
    }
}
