package io.github.jdem846.io.mosaic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.esri.GridFloatFormat;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.DemTiles;
import io.github.jdem846.testing.DemTiles.Cut;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A mosaic opens a file only when a read touches it, and keeps at most a few open: counted through the opener,
 * on 3 × 3 tiles cut from Big Tujunga.
 */
class MosaicSourceTest {

    private static final Path DEM = Path.of("testdata", "dem");

    @TempDir
    static Path tmp;

    private static Dem whole;
    private static List<Path> tiles;

    @BeforeAll
    static void cut() throws IOException {
        whole = DemReader.read(DEM.resolve("bigtujunga_srtm30m_utm11n.flt"));
        List<Cut> cuts = new ArrayList<>();
        int[] xs = {0, 400, 800, 1197};
        int[] ys = {0, 200, 400, 643};
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                cuts.add(new Cut(xs[c], ys[r], xs[c + 1] - xs[c], ys[r + 1] - ys[r]));
            }
        }
        tiles = DemTiles.gridFloat(whole, cuts, tmp, "t", DEM.resolve("bigtujunga_srtm30m_utm11n.prj"));
    }

    @Test
    void aReadOpensOnlyTheFilesItTouches() throws IOException {
        AtomicInteger opened = new AtomicInteger();
        MemberOpener counting = file -> {
            opened.incrementAndGet();
            return GridFloatFormat.open(file);
        };
        MosaicPlan plan = MosaicPlanner.plan(tiles, counting);
        assertEquals(9, opened.get(), "each header read once");
        assertEquals(1197, plan.info().width());
        assertEquals(643, plan.info().height());
        try (MosaicSource source = MosaicSource.open(plan)) {
            assertEquals(0, source.opens(), "nothing opened before a read");
            float[] dst = new float[50 * 40];
            source.readRows(100, 50, 50, 40, dst);        // inside the north-west tile
            assertEquals(1, source.opens());
            assertWindow(dst, 100, 50, 50, 40);
            source.readRows(380, 50, 50, 40, dst);        // across the first seam
            assertEquals(2, source.opens());
            assertWindow(dst, 380, 50, 50, 40);
            source.readRows(780, 380, 50, 40, dst);       // across four tiles not read before
            assertEquals(6, source.opens());
            assertWindow(dst, 780, 380, 50, 40);
        }
        assertEquals(9 + 6, opened.get());
    }

    @Test
    void atMostTheLimitIsOpenAndEveryCellStillReads() throws IOException {
        MosaicPlan plan = MosaicPlanner.plan(tiles, GridFloatFormat::open);
        try (MosaicSource source = MosaicSource.open(plan, 2)) {
            float[] row = new float[1197 * 10];
            for (int r = 0; r < 643; r += 10) {
                int n = Math.min(10, 643 - r);
                source.readRows(0, r, 1197, n, row);
                assertTrue(source.openCount() <= 2, "open: " + source.openCount());
                assertWindow(row, 0, r, 1197, n);
            }
            assertTrue(source.opens() > 9, "files were closed and opened again: " + source.opens());
        }
    }

    @Test
    void aMosaicReportsItsReadingTraits() throws IOException {
        MosaicPlan plan = MosaicPlanner.plan(tiles, GridFloatFormat::open);
        try (MosaicSource source = MosaicSource.open(plan); RasterSource one = GridFloatFormat.open(tiles.get(0))) {
            assertEquals(1, source.naturalRowBlock(), "raw rows");
            assertTrue(source.readsRowsIndependently());
            assertTrue(source.blockBytes() >= 4L * source.bandCells(), "room for the files' cells under a band");
            assertEquals(one.readsRowsIndependently(), source.readsRowsIndependently());
        }
    }

    private static void assertWindow(float[] dst, int col, int row, int w, int h) {
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                assertEquals(whole.get(col + c, row + r), dst[r * w + c], "cell " + (col + c) + "," + (row + r));
            }
        }
    }
}
