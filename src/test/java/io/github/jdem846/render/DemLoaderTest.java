package io.github.jdem846.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.ElevationStatistics;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * The whole file's elevation range that percent tints use: the same for the full picture, a reduced picture and a
 * window, whether it was taken during the read or streamed in a pass of its own.
 */
class DemLoaderTest {

    private static final Path BIG_TUJUNGA = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif");

    @Test
    void aReducedPictureOfTheWholeFileGetsTheFullResolutionRange() throws IOException {
        ElevationStatistics file = DemReader.statistics(BIG_TUJUNGA);
        DemLoader.Loaded quarter = DemLoader.load(BIG_TUJUNGA, null, OutputSize.scale(0.25),
                DemLoader.Halo.NONE, true);
        assertEquals(file, quarter.fileStatistics());
        ElevationStatistics averaged = quarter.dem().statistics();
        assertTrue(averaged.max() < file.max() && averaged.min() > file.min(),
                "box averages narrow the range (" + averaged + "), so the file's range must not come from them");
    }

    @Test
    void windowsAndFullPicturesGetTheWholeFilesRange() throws IOException {
        ElevationStatistics file = DemReader.statistics(BIG_TUJUNGA);
        assertEquals(file, DemLoader.load(BIG_TUJUNGA, null, OutputSize.FULL, DemLoader.Halo.NONE, true)
                .fileStatistics());
        DemLoader.Loaded window = DemLoader.load(BIG_TUJUNGA, Window.cells(100, 50, 300, 200),
                OutputSize.scale(0.5), DemLoader.Halo.uniform(7), true);
        assertEquals(file, window.fileStatistics());
        assertTrue(window.dem().statistics().max() < file.max(), "the window holds not the highest cell");
    }
}
