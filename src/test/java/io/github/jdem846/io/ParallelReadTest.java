package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Reading in row bands through several readers at once gives the same grid as one sequential read: GeoTIFF strips
 * and tiles (subset decoding), GridFloat raw rows, with windows and decimation that do not divide the bands. The
 * statistics taken on the way are those of the window's cells at full resolution, however it was read.
 */
class ParallelReadTest {

    private static final List<String> FILES = List.of(
            "testdata/variants/bigtujunga_crop600x400_v02_int16_lzw_pred2_strip16.tif",
            "testdata/variants/bigtujunga_crop600x400_v05_float32_deflate_pred3_tile256.tif",
            "testdata/variants/bigtujunga_crop600x400_v09_int16_none_strip_bigendian.tif",
            "testdata/variants/luxembourg_n01_float32_nan-nodata_deflate_pred3_tile32.tif",
            "testdata/variants/luxembourg_g01_gridfloat_msbfirst.flt",
            "testdata/dem/bigtujunga_srtm30m_utm11n.tif",
            "testdata/dem/jacksboro_srtm3s_wgs84.flt");

    @Test
    void bandsReadAtOnceEqualOneSequentialRead() throws IOException {
        for (String name : FILES) {
            Path file = Path.of(name);
            DemInfo info = DemReader.inspect(file);
            List<ReadRequest> requests = List.of(ReadRequest.FULL, new ReadRequest(null, 3),
                    new ReadRequest(Window.cells(5, 7, info.width() - 11, info.height() - 9), 1),
                    new ReadRequest(Window.cells(3, 2, info.width() - 4, info.height() - 5), 4));
            for (ReadRequest request : requests) {
                LoadedDem loaded = DemReader.load(file, request, 1, 1);
                Dem sequential = loaded.dem();
                ElevationStatistics fullResolution = ElevationStatistics.of(DemReader.read(file,
                        new ReadRequest(request.window(), 1)).backingArray());
                assertEquals(fullResolution, loaded.sourceStatistics(), name + " " + request);
                for (int parallelism : new int[] {2, 3, 7}) {
                    LoadedDem inBands = DemReader.load(file, request, parallelism, 1);
                    assertEquals(fullResolution, inBands.sourceStatistics(), name + " " + request + " in "
                            + parallelism + " bands");
                    Dem parallel = inBands.dem();
                    assertEquals(sequential.width(), parallel.width());
                    assertEquals(sequential.height(), parallel.height());
                    assertArrayEquals(sequential.backingArray(), parallel.backingArray(),
                            name + " " + request + " in " + parallelism + " bands");
                }
            }
        }
    }

    @Test
    void fileStatisticsStreamedInBandsEqualTheWholeGrids() throws IOException {
        for (String name : FILES) {
            Path file = Path.of(name);
            ElevationStatistics whole = ElevationStatistics.of(DemReader.read(file).backingArray());
            for (int parallelism : new int[] {1, 2, 3, 7}) {
                assertEquals(whole, DemReader.statistics(file, parallelism, 1), name + " in " + parallelism
                        + " bands");
            }
        }
    }
}
