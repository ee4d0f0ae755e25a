package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.LoadedDem;
import io.github.jdem846.io.ReadRequest;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.render.OutputSize;
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

    /**
     * A read at full resolution hands its grid the statistics it took on the way, so that shadows and tints need no
     * pass of their own: they must be exactly those of the grid's cells (no-data, scale and offset applied), and a
     * decimated grid must keep its own.
     */
    @Test
    void theStatisticsAReadTookAreThoseOfItsGrid() throws IOException {
        String[] files = {"testdata/dem/luxembourg_srtm30s_wgs84.tif", "testdata/dem/luxembourg_srtm30s_wgs84.flt",
            "testdata/dem/bigtujunga_srtm30m_utm11n.tif",
            "testdata/formats/volcano_int16_decimetres_scale0.1_offset50_nodata440.tif"};
        ReadRequest[] requests = {ReadRequest.FULL, ReadRequest.of(Window.cells(10, 20, 50, 40)),
            ReadRequest.decimated(3)};
        for (String file : files) {
            for (ReadRequest request : requests) {
                LoadedDem loaded = DemReader.load(Path.of(file), request);
                assertEquals(ElevationStatistics.of(loaded.dem().backingArray()), loaded.dem().statistics(),
                        file + " " + request);
            }
        }
        LoadedDem lux = DemReader.load(Path.of(files[0]), ReadRequest.FULL);
        assertTrue(lux.dem().statistics().noDataCount() > 0, "the no-data rule is part of what is checked");
    }
}
