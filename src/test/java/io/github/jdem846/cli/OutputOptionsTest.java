package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.output.WriteOptions;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** How the output flags and {@code --threads} become {@link WriteOptions}; {@code --cog} end to end. */
class OutputOptionsTest {

    private static final String BT = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";

    @TempDir
    Path dir;

    private static ExecutionOptions threads(Integer n) {
        ExecutionOptions e = new ExecutionOptions();
        e.threads = n;
        return e;
    }

    @Test
    void oneWorkerThreadAlsoCompressesTheOutputOnOneThread() {
        OutputOptions out = new OutputOptions();
        assertFalse(out.writeOptions(threads(1)).parallelCompression(), "--threads 1: PNG and GeoTIFF on one thread");
        assertTrue(out.writeOptions(threads(4)).parallelCompression(), "--threads 4");
        assertEquals(Runtime.getRuntime().availableProcessors() > 1,
                out.writeOptions(threads(null)).parallelCompression(), "default: all processors");
    }

    @Test
    void worldFileFlagCarriesOverAndNoDataIsLeftToTheProduct() {
        OutputOptions out = new OutputOptions();
        assertEquals(WriteOptions.Sidecars.NONE, out.writeOptions(threads(2)).sidecars());
        assertNull(out.writeOptions(threads(2)).noData());
        out.worldFile = true;
        WriteOptions o = out.writeOptions(threads(2));
        assertEquals(WriteOptions.Sidecars.ALWAYS, o.sidecars());
        assertNull(o.noData(), "the product decides: a hillshade marks 0 (ReliefResult.write)");
    }

    @Test
    void cogFlagAsksForTheCogLayout() {
        OutputOptions out = new OutputOptions();
        assertEquals(WriteOptions.TiffLayout.STRIPS, out.writeOptions(threads(2)).tiffLayout(), "default");
        out.cog = true;
        assertEquals(WriteOptions.TiffLayout.COG, out.writeOptions(threads(2)).tiffLayout());
    }

    @Test
    void cogWithAPngIsBadUsageNamingTheOptionAndTheExtensions() throws IOException {
        Path png = dir.resolve("shade.png");
        CliRun run = CliRun.of("hillshade", BT, "-o", png.toString(), "--cog", "-q");
        assertEquals(2, run.exitCode(), run.err());
        String first = run.err().lines().findFirst().orElse("");
        assertTrue(first.startsWith("jdem846: ") && first.contains("'--cog'") && first.contains(".tif or .tiff")
                && first.contains("shade.png"), run.err());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "nothing written");
        }
    }

    /** Big Tujunga is 1197 × 643: tiles of 512 and the two overviews GDAL's COG driver makes, 598×321, 299×160. */
    @Test
    void cogWritesATiledGeoTiffWithOverviews() throws IOException {
        Path tif = dir.resolve("shade.tif");
        CliRun run = CliRun.of("hillshade", BT, "-o", tif.toString(), "--cog", "-q");
        assertEquals(0, run.exitCode(), run.err());
        ImageReader reader = new TIFFImageReaderSpi().createReaderInstance(null);
        try (ImageInputStream in = new FileImageInputStream(tif.toFile())) {
            reader.setInput(in);
            assertEquals(3, reader.getNumImages(true));
            int[][] sizes = {{1197, 643}, {598, 321}, {299, 160}};
            for (int i = 0; i < sizes.length; i++) {
                assertEquals(sizes[i][0], reader.getWidth(i));
                assertEquals(sizes[i][1], reader.getHeight(i));
                assertEquals(512, reader.getTileWidth(i));
            }
        } finally {
            reader.dispose();
        }
    }
}
