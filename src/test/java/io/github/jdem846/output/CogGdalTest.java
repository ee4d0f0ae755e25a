package io.github.jdem846.output;

import static io.github.jdem846.output.CogOutputTest.COG;
import static io.github.jdem846.output.CogOutputTest.GEO;
import static io.github.jdem846.output.CogOutputTest.RELIEF;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.github.jdem846.testing.ExternalTools;
import io.github.jdem846.testing.MiniJson;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Our COGs as GDAL sees them ({@code gdalinfo -json -checksum}; skipped without gdal-bin): {@code LAYOUT=COG}, the
 * overviews GDAL's own COG driver makes of the same picture, the georeferencing and the pixels (checksums) of the
 * stripped GeoTIFF of the same picture, and overviews whose pixels are the box means; BigTIFF too. And GDAL's COG
 * validator, when Python's GDAL bindings are installed.
 */
class CogGdalTest {

    @TempDir
    Path dir;

    @SuppressWarnings("unchecked")
    private static Map<String, Object> gdalinfo(Path file) {
        ExternalTools.Result r = ExternalTools.run(List.of("gdalinfo", "-json", "-checksum", file.toString()));
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.err().isBlank(), "no warning: " + r.err());
        return (Map<String, Object>) MiniJson.parse(r.out());
    }

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> bands(Map<String, Object> info) {
        return (List<Map<String, Object>>) info.get("bands");
    }

    @SuppressWarnings("unchecked")
    private static String imageStructure(Map<String, Object> info, String key) {
        Map<String, Object> metadata = (Map<String, Object>) info.get("metadata");
        return (String) ((Map<String, Object>) metadata.get("IMAGE_STRUCTURE")).get(key);
    }

    @SuppressWarnings("unchecked")
    private static List<Object> overviews(Map<String, Object> band, String key) {
        List<Object> out = new ArrayList<>();
        for (Map<String, Object> o : (List<Map<String, Object>>) band.get("overviews")) {
            out.add(o.get(key));
        }
        return out;
    }

    @SuppressWarnings("unchecked")
    private static Object epsg(Map<String, Object> info) {
        return ((Map<String, Object>) info.get("stac")).get("proj:epsg");
    }

    @Test
    void gdalReadsACogWithGdalsOverviewsOurGeoreferencingAndPixels() throws IOException {
        assumeTrue(ExternalTools.onPath("gdalinfo") && ExternalTools.onPath("gdal_translate"), "gdal-bin absent");
        int w = RELIEF.width();
        int h = RELIEF.height();
        Path strips = dir.resolve("strips.tif");
        Path cog = dir.resolve("cog.tif");
        WriteOptions noData = WriteOptions.defaults().withNoData(0);
        ImageOutput.writeGray(strips, RELIEF.gray(), w, h, GEO, noData);
        ImageOutput.writeGray(cog, RELIEF.gray(), w, h, GEO, COG.withNoData(0));
        Path gdalsCog = dir.resolve("gdal-cog.tif");
        ExternalTools.Result translated = ExternalTools.run(List.of("gdal_translate", "-q", "-of", "COG", "-co",
                "BLOCKSIZE=" + CogOutputTest.TILE, strips.toString(), gdalsCog.toString()));
        assertEquals(0, translated.exitCode(), translated.err());

        Map<String, Object> ours = gdalinfo(cog);
        Map<String, Object> reference = gdalinfo(strips);
        Map<String, Object> band = bands(ours).get(0);
        assertEquals("COG", imageStructure(ours, "LAYOUT"));
        assertEquals("DEFLATE", imageStructure(ours, "COMPRESSION"));
        assertEquals("2", imageStructure(ours, "PREDICTOR"));
        assertEquals(List.of((double) CogOutputTest.TILE, (double) CogOutputTest.TILE), band.get("block"));
        assertEquals(overviews(bands(gdalinfo(gdalsCog)).get(0), "size"), overviews(band, "size"),
                "the overviews GDAL's COG driver makes");
        assertEquals(4, overviews(band, "size").size());
        assertEquals(reference.get("geoTransform"), ours.get("geoTransform"));
        assertEquals(32611.0, epsg(ours));
        assertEquals(0.0, band.get("noDataValue"));
        assertEquals(bands(reference).get(0).get("checksum"), band.get("checksum"), "full-resolution pixels");
        List<Object> checksums = overviews(band, "checksum");
        for (int k = 1; k <= 4; k++) {
            Path means = dir.resolve("means" + k + ".tif");
            int[] expected = CogOutputTest.grayMeans(RELIEF.gray(), w, h, k, 0);
            byte[] bytes = new byte[expected.length];
            for (int i = 0; i < bytes.length; i++) {
                bytes[i] = (byte) expected[i];
            }
            ImageOutput.writeGray(means, bytes, CogOutputTest.levelSize(w, k), CogOutputTest.levelSize(h, k), null,
                    noData);
            assertEquals(bands(gdalinfo(means)).get(0).get("checksum"), checksums.get(k - 1), "overview " + k);
        }
    }

    @Test
    void gdalReadsRgbaCogsClassicAndBigAndBigStrips() throws IOException {
        assumeTrue(ExternalTools.onPath("gdalinfo"), "gdal-bin absent");
        int w = RELIEF.width();
        int h = RELIEF.height();
        int[] argb = CogOutputTest.rgba();
        Path strips = dir.resolve("strips.tif");
        ImageOutput.writeRgba(strips, argb, w, h, GEO, WriteOptions.defaults());
        Path cog = dir.resolve("cog.tif");
        ImageOutput.writeRgba(cog, argb, w, h, GEO, COG);
        Path big = dir.resolve("big.tif");
        Path bigStrips = dir.resolve("big-strips.tif");
        for (Path file : List.of(big, bigStrips)) {
            WriteOptions options = file == big ? COG : WriteOptions.defaults();
            try (FileImageSink sink = FileImageSink.open(file, w, h, 4, 8, GEO, options, null, 1000)) {
                sink.appendRgba(argb, h);
                sink.commit();
            }
        }
        Map<String, Object> strip = gdalinfo(strips);
        List<Map<String, Object>> reference = bands(strip);
        for (Path file : List.of(cog, big, bigStrips)) {
            Map<String, Object> info = gdalinfo(file);
            if (file != bigStrips) {
                assertEquals("COG", imageStructure(info, "LAYOUT"), file.toString());
            }
            assertEquals(strip.get("geoTransform"), info.get("geoTransform"), file.toString());
            assertEquals(4, bands(info).size());
            assertEquals("Alpha", bands(info).get(3).get("colorInterpretation"));
            for (int b = 0; b < 4; b++) {
                assertEquals(reference.get(b).get("checksum"), bands(info).get(b).get("checksum"), file + " " + b);
                assertEquals(file == bigStrips ? 0 : 4, bands(info).get(b).containsKey("overviews")
                        ? overviews(bands(info).get(b), "size").size() : 0);
            }
        }
    }

    /** GDAL's validate_cloud_optimized_geotiff.py, with its full check of tile leaders and trailers. */
    @Test
    void gdalsValidatorFindsAValidCog() throws IOException {
        String python = null;
        for (String candidate : List.of("python3", "/usr/bin/python3")) {
            boolean found = candidate.startsWith("/") ? Files.isExecutable(Path.of(candidate))
                    : ExternalTools.onPath(candidate);
            if (found && ExternalTools.run(List.of(candidate,
                    "-c", "from osgeo_utils.samples import validate_cloud_optimized_geotiff")).exitCode() == 0) {
                python = candidate;
                break;
            }
        }
        assumeTrue(python != null, "Python's GDAL bindings (osgeo_utils) absent");
        Path gray = dir.resolve("gray.tif");
        ImageOutput.writeGray(gray, RELIEF.gray(), RELIEF.width(), RELIEF.height(), GEO, COG.withNoData(0));
        Path big = dir.resolve("big.tif");
        try (FileImageSink sink = FileImageSink.open(big, RELIEF.width(), RELIEF.height(), 4, 8, GEO, COG, null, 1000)) {
            sink.appendRgba(CogOutputTest.rgba(), RELIEF.height());
            sink.commit();
        }
        for (Path file : List.of(gray, big)) {
            ExternalTools.Result r = ExternalTools.run(List.of(python, "-m",
                    "osgeo_utils.samples.validate_cloud_optimized_geotiff", "--full-check=yes", file.toString()));
            assertEquals(0, r.exitCode(), r.out() + r.err());
            assertTrue(r.out().contains("is a valid cloud optimized GeoTIFF"), r.out());
            assertTrue(!r.out().contains("warning"), r.out());
        }
    }
}
