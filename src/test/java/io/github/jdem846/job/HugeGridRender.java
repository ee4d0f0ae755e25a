package io.github.jdem846.job;

import io.github.jdem846.output.ImageSink;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Renders the hillshade of a flat DEM (elevation 0 everywhere) of more cells than one Java array holds, in tiles,
 * in a JVM of its own started with a small heap ({@link HugeGridTest}). Every pixel is checked as its band arrives
 * against the hillshade of a small flat DEM with the same header (corners, edges and inside); nothing is written:
 * the image file of a picture this size needs a streaming {@link ImageSink}, which {@link ReliefJob#runAndWrite} is
 * handed the same way. After {@code bands} bands (0 = all) the sink interrupts the job, which must then stop with
 * {@link InterruptedException} and close the sink without committing it.
 *
 * <p>Prints one line: {@code ok <width> <height> <rows checked> <progress total> <peak heap MiB> <tiles across>
 * <tiles down> <committed>}, or what was wrong, exit status 1.
 */
public final class HugeGridRender {

    private HugeGridRender() {
    }

    /** @param args the huge DEM, a small flat DEM with the same header but 5 × 5 cells, the bands to check */
    public static void main(String[] args) throws Exception {
        Path huge = Path.of(args[0]);
        Path small = Path.of(args[1]);
        int bands = Integer.parseInt(args[2]);
        RenderSettings threads = new RenderSettings(Runtime.getRuntime().availableProcessors(), 256);
        Scene horn = Scene.defaults().withHillshade(HillshadeMethod.HORN);
        ReliefJob hillshade = ReliefJob.of(huge).withProduct(Product.HILLSHADE).withExecution(threads)
                .withScene(horn);
        byte[] expected = ReliefJob.of(small).withProduct(Product.HILLSHADE).withExecution(threads).withScene(horn)
                .run(JobListener.NONE).gray();
        List<String> notices = new ArrayList<>();
        long[] total = new long[1];
        Checker checker = new Checker(expected, bands);
        try {
            hillshade.runAndWrite((picture, rgba) -> checker.open(picture.width(), picture.height()),
                    result -> {
                        throw new IllegalStateException("a grid of more than 2³¹ cells was rendered in memory");
                    }, new JobListener() {
                        @Override
                        public void notice(String message) {
                            notices.add(message);
                        }

                        @Override
                        public void update(String stage, long done, long t) {
                            total[0] = t;
                        }
                    });
        } catch (InterruptedException stopped) {
            if (bands == 0 || checker.rows == checker.height || checker.open) {
                fail("stopped after " + checker.rows + " rows, the sink " + (checker.open ? "open" : "closed"));
            }
        }
        int[] tiles = TiledRenderTest.tiles(notices);
        System.out.printf(Locale.ROOT, "ok %d %d %d %d %d %d %d %b%n", checker.width, checker.height, checker.rows,
                total[0], checker.peak >> 20, tiles[0], tiles[1], checker.committed);
    }

    private static void fail(String message) {
        System.out.println(message);
        System.exit(1);
    }

    /** Checks each band of gray rows against the small flat DEM's hillshade; interrupts after {@code bands}. */
    private static final class Checker implements ImageSink {
        private final byte[] small;
        private final int bands;
        private int width;
        private int height;
        private int rows;
        private int appended;
        private long peak;
        private boolean open;
        private boolean committed;

        Checker(byte[] small, int bands) {
            this.small = small;
            this.bands = bands;
        }

        ImageSink open(int w, int h) {
            width = w;
            height = h;
            open = true;
            return this;
        }

        @Override
        public int width() {
            return width;
        }

        @Override
        public int height() {
            return height;
        }

        @Override
        public int rowsWritten() {
            return rows;
        }

        @Override
        public void appendRgba(int[] argb, int count) {
            fail("a hillshade is gray");
        }

        @Override
        public void appendGray(byte[] gray, int count) {
            for (int r = 0; r < count; r++, rows++) {
                int sr = rows == 0 ? 0 : rows == height - 1 ? 4 : 2;
                for (int c = 0; c < width; c++) {
                    int sc = c == 0 ? 0 : c == width - 1 ? 4 : 2;
                    if (gray[r * width + c] != small[sr * 5 + sc]) {
                        fail("pixel " + c + "," + rows + " is " + (gray[r * width + c] & 255) + ", the small DEM's "
                                + (small[sr * 5 + sc] & 255));
                    }
                }
            }
            Runtime rt = Runtime.getRuntime();
            peak = Math.max(peak, rt.totalMemory() - rt.freeMemory());
            if (++appended == bands) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public WriteResult commit() {
            if (rows != height) {
                fail(rows + " of " + height + " rows were appended before the commit");
            }
            committed = true;
            return new WriteResult(Path.of("checked"), List.of(), List.of());
        }

        @Override
        public void close() {
            open = false;
        }
    }
}
