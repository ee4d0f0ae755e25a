package io.github.jdem846.projection;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.output.ImageSink;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.io.ByteArrayOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A projected picture warped band by band, reading only the rows of the source each band needs, is the same, byte
 * for byte, as the picture warped whole: in memory ({@link PictureWarp#warpBands} against {@link
 * PictureWarp#warp}) and as files ({@link ProjectedRender#runAndWrite} under a memory budget far too small, the
 * relief then rendered in tiles to a temporary GeoTIFF), for RGBA and gray products.
 */
class ProjectedBandsTest {

    private static final Path JACKSBORO = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif");

    /** Collects the bands appended, and the largest. */
    private static final class Collecting implements ImageSink {
        private final int width;
        private final int height;
        private final int[] argb;
        private final byte[] gray;
        private int rows;
        private int bands;

        Collecting(int width, int height) {
            this.width = width;
            this.height = height;
            this.argb = new int[width * height];
            this.gray = new byte[width * height];
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
        public void appendRgba(int[] band, int n) {
            System.arraycopy(band, 0, argb, rows * width, n * width);
            rows += n;
            bands++;
        }

        @Override
        public void appendGray(byte[] band, int n) {
            System.arraycopy(band, 0, gray, rows * width, n * width);
            rows += n;
            bands++;
        }

        @Override
        public WriteResult commit() {
            throw new UnsupportedOperationException();
        }

        @Override
        public void close() {
        }
    }

    /** A source in memory that counts the rows read at once. */
    private static final class Memory implements PictureWarp.RowReader {
        private final int[] argb;
        private final byte[] gray;
        private final int width;
        private final List<Integer> windows = new ArrayList<>();

        Memory(int[] argb, byte[] gray, int width) {
            this.argb = argb;
            this.gray = gray;
            this.width = width;
        }

        @Override
        public boolean rgba() {
            return argb != null;
        }

        @Override
        public int[] rgbaRows(int first, int count) {
            windows.add(count);
            return Arrays.copyOfRange(argb, first * width, (first + count) * width);
        }

        @Override
        public byte[] grayRows(int first, int count) {
            windows.add(count);
            return Arrays.copyOfRange(gray, first * width, (first + count) * width);
        }
    }

    private static GridGeometry world() {
        return new GridGeometry(360, 180, -180, 90, 1, 1, CrsInfo.WGS84, PixelAnchor.CORNER);
    }

    @Test
    void bandsEqualTheWholeWarp() throws Exception {
        GridGeometry grid = world();
        int[] argb = new int[360 * 180];
        byte[] gray = new byte[360 * 180];
        for (int i = 0; i < argb.length; i++) {
            int col = i % 360;
            int row = i / 360;
            argb[i] = (col * 7 + row * 3) % 5 == 0 ? 0 : 0xFF000000 | (col * 0x10305 + row * 0x30107) & 0xFFFFFF;
            gray[i] = (byte) ((col + 2 * row) % 9 == 0 ? 0 : 1 + (col * 13 + row * 7) % 255);
        }
        RenderSettings threads = new RenderSettings(2, 256);
        for (ProjectionName name : new ProjectionName[] {ProjectionName.WINKEL_TRIPEL, ProjectionName.ROBINSON,
                ProjectionName.MERCATOR}) {
            MapProjection projection = MapProjection.named(name, 30);
            ProjectedExtent extent = ProjectedExtent.of(grid, projection);
            int[] size = extent.pixels(500, 0);
            int[] whole = PictureWarp.warp(argb, grid, projection, extent, size[0], size[1], threads);
            byte[] wholeGray = PictureWarp.warpGray(gray, 0, grid, projection, extent, size[0], size[1], threads);
            long budget = 60_000; // a band of a few rows, a window of at most ~80 of the 180 rows
            Collecting sink = new Collecting(size[0], size[1]);
            Memory source = new Memory(argb, null, 360);
            PictureWarp.warpBands(source, null, grid, projection, extent, sink, budget, threads);
            assertArrayEquals(whole, sink.argb, name + " RGBA");
            assertTrue(sink.bands > 10, name + ": " + sink.bands + " bands");
            assertTrue(source.windows.stream().allMatch(n -> n * 360L * 4 <= budget / 2), name + " windows "
                    + source.windows);
            Collecting graySink = new Collecting(size[0], size[1]);
            PictureWarp.warpBands(new Memory(null, gray, 360), 0, grid, projection, extent, graySink, budget / 4,
                    threads);
            assertArrayEquals(wholeGray, graySink.gray, name + " gray");
        }
    }

    /** A flat DEM's picture compresses a thousandfold: the temporary file must still be read back. */
    @Test
    void aFlatDemInBands(@TempDir Path dir) throws Exception {
        int cols = 1800;
        int rows = 900;
        java.nio.ByteBuffer cells = java.nio.ByteBuffer.allocate(4 * cols * rows)
                .order(java.nio.ByteOrder.LITTLE_ENDIAN);
        while (cells.hasRemaining()) {
            cells.putFloat(100f);
        }
        Files.write(dir.resolve("flat.flt"), cells.array());
        Files.writeString(dir.resolve("flat.hdr"), "ncols " + cols + "\nnrows " + rows + "\nxllcorner -180\n"
                + "yllcorner -90\ncellsize 0.2\nNODATA_value -9999\nbyteorder LSBFIRST\n");
        Files.copy(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.prj"), dir.resolve("flat.prj"));
        ReliefJob job = ReliefJob.of(dir.resolve("flat.flt"));
        ProjectedRender render = new ProjectedRender(MapProjection.named(ProjectionName.WINKEL_TRIPEL, 0), 800, 0);
        Path whole = dir.resolve("whole.tif");
        Path bands = dir.resolve("bands.tif");
        render.runAndWrite(job, whole, WriteOptions.defaults(), JobListener.NONE);
        render.runAndWrite(job.withMemory(2_000_000), bands, WriteOptions.defaults(), JobListener.NONE);
        assertEquals(-1, Files.mismatch(whole, bands));
    }

    @Test
    void aBudgetTooSmallForOneRowIsRefused() {
        GridGeometry grid = world();
        MapProjection projection = MapProjection.named(ProjectionName.WINKEL_TRIPEL, 0);
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        Collecting sink = new Collecting(400, 245);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> PictureWarp.warpBands(
                new Memory(new int[360 * 180], null, 360), null, grid, projection, extent, sink, 2_000,
                new RenderSettings(1, 256)));
        assertTrue(e.getMessage().contains("memory budget"), e.getMessage());
    }

    @Test
    void filesWrittenInBandsEqualFilesWrittenWhole(@TempDir Path dir) throws Exception {
        WriteOptions options = WriteOptions.defaults();
        for (Product product : new Product[] {Product.RELIEF, Product.HILLSHADE, Product.SHADOWS}) {
            for (String ext : new String[] {"png", "tif"}) {
                ReliefJob job = ReliefJob.of(JACKSBORO).withProduct(product);
                job = job.withScene(job.scene().withShadows(ShadowAlgorithm.SWEEP)); // cast shadows: a wide halo
                ProjectedRender render = new ProjectedRender(MapProjection.named(ProjectionName.WINKEL_TRIPEL, 0),
                        300, 0);
                Path whole = dir.resolve("whole-" + product + "." + ext);
                Path bands = dir.resolve("bands-" + product + "." + ext);
                List<String> notices = new ArrayList<>();
                render.runAndWrite(job, whole, options, JobListener.NONE);
                render.runAndWrite(job.withMemory(400_000), bands, options, new JobListener() {
                    @Override
                    public void notice(String message) {
                        notices.add(message);
                    }
                });
                assertTrue(notices.stream().anyMatch(n -> n.contains("warping it in bands")), product + " " + notices);
                assertTrue(notices.stream().anyMatch(n -> n.contains("tiles")), product + " relief in tiles " + notices);
                assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(bands), product + " " + ext);
                try (var files = Files.list(dir)) {
                    assertEquals(0, files.filter(f -> f.getFileName().toString().startsWith(".")).count(),
                            "no temporary file is left");
                }
            }
        }
    }
}
