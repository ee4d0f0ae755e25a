package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The range measured in row bands (as a cluster measures it, one band per task) and merged equals the range of the
 * whole grid and the range of the cells read into memory, for three real DEMs (GridFloat and GeoTIFF).
 */
class WindowStatisticsTest {

    @ParameterizedTest
    @ValueSource(strings = {TestDems.BIG_TUJUNGA + ".flt", TestDems.JACKSBORO + ".tif",
            TestDems.VANCOUVER + ".tif"})
    void bandsMergedAreTheWhole(String name) throws IOException {
        DemInput input = DemInput.of(TestDems.DEM_DIR.resolve(name));
        DemInfo info = DemReader.inspect(input);
        ElevationStatistics merged = null;
        int bandRows = info.height() / 3 + 1;
        for (int row = 0; row < info.height(); row += bandRows) {
            ElevationStatistics band = DemReader.statistics(input,
                    new Window.Cells(0, row, info.width(), Math.min(bandRows, info.height() - row)));
            merged = merged == null ? band : merged.merge(band);
        }
        assertEquals(DemReader.statistics(input), merged);
        Dem dem = DemReader.read(input, ReadRequest.FULL);
        assertEquals(ElevationStatistics.of(dem.backingArray()), merged);
    }

    @Test
    void aWindowOutsideTheGridIsRefused() throws IOException {
        DemInput input = DemInput.of(TestDems.DEM_DIR.resolve(TestDems.JACKSBORO + ".tif"));
        DemInfo info = DemReader.inspect(input);
        assertThrows(IllegalArgumentException.class, () -> DemReader.statistics(input,
                new Window.Cells(0, 0, info.width() + 1, 1)));
        assertThrows(IllegalArgumentException.class, () -> DemReader.statistics(input,
                new Window.Cells(0, info.height(), info.width(), 1)));
    }
}
