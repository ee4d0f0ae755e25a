package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import org.junit.jupiter.api.Test;

/** The shared read of a small DEM gives the cells a windowed, decimated read of the file gives. */
class OverviewTest {

    @Test
    void cellsEqualAWindowedDecimatedRead() throws Exception {
        DemInput input = DemInput.of(SourceSamplingTest.DEM);
        Overview overview = Overview.read(input, 4);
        Window.Cells window = Window.cells(400, 120, 520, 300); // on whole blocks of 8 cells
        Dem direct4 = DemReader.load(input, new ReadRequest(window, 4)).dem();
        Dem shared4 = overview.cells(window, 1);
        assertArrayEquals(direct4.backingArray(), shared4.backingArray(), 0f);
        assertEquals(direct4.geometry(), shared4.geometry());
        // blocks of 2 × 2 blocks of 4: the blocks of 8 of the file (no no-data here), up to float rounding
        Dem direct8 = DemReader.load(input, new ReadRequest(window, 8)).dem();
        Dem shared8 = overview.cells(window, 2);
        assertEquals(direct8.width(), shared8.width());
        assertEquals(direct8.height(), shared8.height());
        assertArrayEquals(direct8.backingArray(), shared8.backingArray(), 1e-3f);
        assertEquals(direct8.geometry().originX(), shared8.geometry().originX(), 1e-6);
        assertEquals(direct8.geometry().cellWidth(), shared8.geometry().cellWidth(), 1e-9);
    }

    @Test
    void averagesSkipNoDataAndKeepPartialBlocks() {
        float n = Float.NaN;
        Dem dem = new Dem(new float[] {
            1, 3, 5, 7, 9,
            n, 2, 6, n, 1,
            n, n, 4, 4, 8}, GridGeometry.metric(5, 3, 10));
        Dem avg = Overview.average(dem, 2);
        assertEquals(3, avg.width());
        assertEquals(2, avg.height());
        assertArrayEquals(new float[] {2, 6, 5, n, 4, 8}, avg.backingArray(), 0f);
        assertEquals(20, avg.geometry().cellWidth(), 0);
    }
}
