package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.testing.TestDems;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * How tiles read a projected DEM (Big Tujunga, UTM 11N, 30 m): each zoom reads only the cells under its tiles,
 * box-averaged to about one cell per pixel; pixel positions interpolated on a lattice agree with exact ones, and a
 * pixel gets the same elevation in every block that samples it.
 */
class SourceSamplingTest {

    static final Path DEM = TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ".tif");

    private static SourceProjection projection() throws Exception {
        DemInfo info = DemReader.inspect(DemInput.of(DEM)).withDefaultEllipsoid(Ellipsoid.WGS84);
        return SourceProjection.of(info.geometry(), info.source());
    }

    @Test
    void lowZoomsReadDecimatedCells() throws Exception {
        SourceProjection projection = projection();
        // a zoom-8 pixel is 611.5 m of Web Mercator, 611.5 · cos 34.3° = 505 m on the ground: 16.8 cells of 30 m
        ZoomGrid z8 = new ZoomGrid(8);
        ZoomSource source = new ZoomSource(DemInput.of(DEM), projection, z8);
        double ground = WebMercatorTile.pixelSize(8) * Math.cos(Math.toRadians(34.3)) / 30;
        assertTrue(Math.abs(source.decimation() - Math.floor(ground)) <= 1, source.decimation() + " vs " + ground);
        TileRange range = TileRange.covering(projection.extent(), 8);
        WebMercatorTile t = range.tiles().get(0);
        CellWindow core = TileRasterizer.core(t);
        Window.Cells cells = source.cellsFor(core);
        assertEquals(0, cells.col() % source.decimation(), "windows start on whole blocks");
        assertEquals(0, cells.row() % source.decimation());
        // at zoom 12 a group of tiles reads a window, not the grid
        ZoomGrid z12 = new ZoomGrid(12);
        ZoomSource deep = new ZoomSource(DemInput.of(DEM), projection, z12);
        assertEquals(1, deep.decimation());
        double lon = -118.15;
        double lat = 34.32;
        int col = (int) ((WebMercator.x(lon) + WebMercator.HALF_WORLD) / WebMercatorTile.pixelSize(12));
        int row = (int) ((WebMercator.HALF_WORLD - WebMercator.y(lat)) / WebMercatorTile.pixelSize(12));
        Window.Cells w = deep.cellsFor(new CellWindow(col, row, 256, 256));
        assertTrue(w.width() < 400 && w.height() < 400, "a 256-pixel tile of 31 m pixels reads " + w);
        assertTrue(w.width() > 256 && w.height() > 256, w.toString());
    }

    @Test
    void latticePositionsAgreeWithExactOnesAndAcrossBlocks() throws Exception {
        SourceProjection projection = projection();
        ZoomGrid z12 = new ZoomGrid(12);
        ZoomSource source = new ZoomSource(DemInput.of(DEM), projection, z12);
        assertTrue(source.latticeStep() >= 8, "UTM is smooth over a few pixels: step " + source.latticeStep());
        int col = (int) ((WebMercator.x(-118.15) + WebMercator.HALF_WORLD) / WebMercatorTile.pixelSize(12));
        int row = (int) ((WebMercator.HALF_WORLD - WebMercator.y(34.32)) / WebMercatorTile.pixelSize(12));
        CellWindow block = new CellWindow(col, row, 160, 160);
        Window.Cells cells = source.cellsFor(block);
        Dem dem = DemReader.load(DemInput.of(DEM), new ReadRequest(cells, 1)).dem();
        float[] lattice = new SourceWindow(dem, projection, source.latticeStep()).sample(z12, col, row, 160, 160);
        float[] exact = new SourceWindow(dem, projection, 1).sample(z12, col, row, 160, 160);
        double worst = 0;
        double sum = 0;
        for (int i = 0; i < exact.length; i++) {
            assertTrue(!Float.isNaN(exact[i]), "the block lies inside the DEM");
            double d = Math.abs(lattice[i] - exact[i]);
            worst = Math.max(worst, d);
            sum += d;
        }
        System.out.printf(java.util.Locale.ROOT, "lattice step %d: elevations within %.3f m of exact, mean %.4f m%n",
                source.latticeStep(), worst, sum / exact.length);
        assertTrue(worst < 0.5, "worst " + worst + " m");
        assertTrue(sum / exact.length < 0.05, "mean " + sum / exact.length + " m");
        // another block overlapping this one by 100 × 100 pixels samples them identically
        float[] shifted = new SourceWindow(dem, projection, source.latticeStep()).sample(z12, col + 60, row + 60,
                100, 100);
        for (int r = 0; r < 100; r++) {
            for (int c = 0; c < 100; c++) {
                assertEquals(lattice[(r + 60) * 160 + c + 60], shifted[r * 100 + c], 0f);
            }
        }
    }
}
