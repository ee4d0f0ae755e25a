package io.github.jdem846.io;

import static io.github.jdem846.io.DemAssertions.assertSameGeotransform;
import static io.github.jdem846.io.DemAssertions.assertSameValues;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.DemTiles;
import io.github.jdem846.testing.DemTiles.Cut;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * GDAL virtual rasters read as mosaics: a VRT written here by hand and one written by gdalbuildvrt read as the DEM
 * their tiles were cut from; overlaps follow GDAL (checked against gdal_translate's reading of the same VRT);
 * what a VRT can say that is not supported is refused with a message naming it.
 */
class VrtReadTest {

    private static final Path DEM = Path.of("testdata", "dem");

    @TempDir
    static Path tmp;

    private static Dem jacksboro;
    private static List<Cut> cuts;
    private static List<Path> tiles;

    @BeforeAll
    static void cut() throws IOException {
        jacksboro = DemReader.read(DEM.resolve("jacksboro_srtm3s_wgs84.tif"));
        cuts = DemTiles.quarters(403, 344, 200, 170, 1);
        tiles = DemTiles.geoTiff(jacksboro, cuts, Files.createDirectories(tmp.resolve("tiles")), "j", 4326, true);
    }

    /** A VRT of the tiles, SimpleSources and ComplexSources, paths relative to the VRT. */
    private static String handWritten(String srs, String extraBand, String extraSource) {
        StringBuilder sb = new StringBuilder();
        var g = jacksboro.geometry();
        sb.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<VRTDataset rasterXSize=\"403\" rasterYSize=\"344\">\n");
        if (srs != null) {
            sb.append("  <SRS>").append(srs).append("</SRS>\n");
        }
        sb.append(String.format(Locale.ROOT, "  <GeoTransform>%s, %s, 0, %s, 0, -%s</GeoTransform>%n",
                DemTiles.plain(g.originX()), DemTiles.plain(g.cellWidth()), DemTiles.plain(g.originY()),
                DemTiles.plain(g.cellHeight())));
        sb.append("  <VRTRasterBand dataType=\"Float32\" band=\"1\">\n    <NoDataValue>-9999</NoDataValue>\n")
                .append(extraBand);
        for (int i = 0; i < tiles.size(); i++) {
            Cut c = cuts.get(i);
            String kind = i % 2 == 0 ? "SimpleSource" : "ComplexSource";
            sb.append("    <").append(kind).append(">\n      <SourceFilename relativeToVRT=\"1\">tiles/")
                    .append(tiles.get(i).getFileName()).append("</SourceFilename>\n")
                    .append("      <SourceBand>1</SourceBand>\n")
                    .append(rect("SrcRect", 0, 0, c.width(), c.height()))
                    .append(rect("DstRect", c.col(), c.row(), c.width(), c.height()));
            if (kind.equals("ComplexSource")) {
                sb.append("      <NODATA>-9999</NODATA>\n");
            }
            if (i == 0) {
                sb.append(extraSource);
            }
            sb.append("    </").append(kind).append(">\n");
        }
        sb.append("  </VRTRasterBand>\n</VRTDataset>\n");
        return sb.toString();
    }

    private static String rect(String tag, int x, int y, int w, int h) {
        return String.format(Locale.ROOT, "      <%s xOff=\"%d\" yOff=\"%d\" xSize=\"%d\" ySize=\"%d\"/>%n",
                tag, x, y, w, h);
    }

    private static Path write(String name, String xml) throws IOException {
        Path vrt = tmp.resolve(name);
        Files.writeString(vrt, xml, StandardCharsets.UTF_8);
        return vrt;
    }

    @Test
    void aHandWrittenVrtReadsAsTheDemItsTilesWereCutFrom() throws IOException {
        Path vrt = write("hand.vrt", handWritten(Files.readString(DEM.resolve("jacksboro_srtm3s_wgs84.prj")), "",
                ""));
        LoadedDem loaded = DemReader.load(DemInput.of(vrt), ReadRequest.FULL);
        assertSameValues(jacksboro, loaded.dem(), "hand-written VRT");
        assertSameGeotransform(jacksboro.geometry(), loaded.dem().geometry(), 1e-15, "hand-written VRT");
        DemInfo info = loaded.info();
        assertEquals(DemFormat.VRT, info.format());
        assertEquals(vrt.toString(), info.source());
        assertEquals(4, info.members().size());
        assertEquals(4326, info.geometry().crs().epsg());
        assertTrue(info.notices().stream().anyMatch(n -> n.contains("last source")), info.notices().toString());
        // a window across the seams, decimated
        ReadRequest r = new ReadRequest(Window.cells(150, 120, 120, 100), 3);
        assertSameValues(DemReader.read(DemInput.of(DEM.resolve("jacksboro_srtm3s_wgs84.tif")), r),
                DemReader.read(DemInput.of(vrt), r), "window");
        // outputs must not overwrite the VRT or its tiles
        List<Path> files = DemReader.filesOf(vrt);
        assertEquals(5, files.size(), files.toString());
        assertEquals(vrt, files.get(0));
        for (Path t : tiles) {
            assertTrue(files.contains(t), t + " in " + files);
        }
    }

    @Test
    void theLastSourceWithAValidValueWins() throws IOException {
        Path dir = Files.createDirectories(tmp.resolve("last"));
        Cut a = new Cut(0, 0, 120, 80);
        Cut b = new Cut(100, 20, 120, 80);
        float[] va = DemTiles.cells(jacksboro, a);
        float[] vb = DemTiles.cells(jacksboro, b);
        for (int i = 0; i < vb.length; i++) {
            vb[i] += 2;
        }
        vb[5 * 120 + 3] = DemTiles.NO_DATA;  // (103, 25): the first source shows through
        var g = jacksboro.geometry();
        DemTiles.writeGeoTiff(dir.resolve("a.tif"), va, 120, 80, g.originX(), g.originY(), g.cellWidth(),
                g.cellHeight(), 4326, true);
        var gb = g.window(b.col(), b.row(), b.width(), b.height());
        DemTiles.writeGeoTiff(dir.resolve("b.tif"), vb, 120, 80, gb.originX(), gb.originY(), gb.cellWidth(),
                gb.cellHeight(), 4326, true);
        String xml = "<VRTDataset rasterXSize=\"220\" rasterYSize=\"100\">"
                + "<VRTRasterBand dataType=\"Float32\" band=\"1\"><NoDataValue>-9999</NoDataValue>"
                + "<ComplexSource><SourceFilename relativeToVRT=\"1\">a.tif</SourceFilename><NODATA>-9999</NODATA>"
                + "<SrcRect xOff=\"0\" yOff=\"0\" xSize=\"120\" ySize=\"80\"/>"
                + "<DstRect xOff=\"0\" yOff=\"0\" xSize=\"120\" ySize=\"80\"/></ComplexSource>"
                + "<ComplexSource><SourceFilename relativeToVRT=\"1\">b.tif</SourceFilename><NODATA>-9999</NODATA>"
                + "<SrcRect xOff=\"0\" yOff=\"0\" xSize=\"120\" ySize=\"80\"/>"
                + "<DstRect xOff=\"100\" yOff=\"20\" xSize=\"120\" ySize=\"80\"/></ComplexSource>"
                + "</VRTRasterBand></VRTDataset>";
        Path vrt = dir.resolve("last.vrt");
        Files.writeString(vrt, xml);
        Dem m = DemReader.read(DemInput.of(vrt), ReadRequest.FULL);
        // no GeoTransform: the grid is that of the first source
        assertEquals(g.originX(), m.geometry().originX());
        assertEquals(g.originY(), m.geometry().originY());
        for (int r = 0; r < 100; r++) {
            for (int c = 0; c < 220; c++) {
                boolean inA = c < 120 && r < 80;
                boolean inB = c >= 100 && r >= 20;
                float expected = inB && !(c == 103 && r == 25) ? jacksboro.get(c, r) + 2
                        : inA ? jacksboro.get(c, r) : Float.NaN;
                assertEquals(expected, m.get(c, r), "cell " + c + "," + r);
            }
        }
        // GDAL's own reading of the same VRT (its gaps are the band's NoDataValue, 0 without one: here -9999)
        assumeTrue(onPath("gdal_translate"), "gdal_translate is not installed");
        Path gdal = dir.resolve("gdal.tif");
        run(dir, "gdal_translate", "-q", "-ot", "Float32", "last.vrt", "gdal.tif");
        assertSameValues(DemReader.read(gdal), m, "gdal_translate of the VRT");
    }

    @Test
    void aVrtFromGdalbuildvrtReadsAsTheWholeDemAndAsGdalReadsIt() throws IOException {
        assumeTrue(onPath("gdalbuildvrt") && onPath("gdal_translate"), "gdalbuildvrt is not installed");
        Path dir = tmp.resolve("tiles");
        List<String> cmd = new ArrayList<>(List.of("gdalbuildvrt", "-q", "built.vrt"));
        for (Path t : tiles) {
            cmd.add(t.getFileName().toString());
        }
        run(dir, cmd.toArray(new String[0]));
        Path vrt = dir.resolve("built.vrt");
        String xml = Files.readString(vrt);
        assertTrue(xml.contains("<VRTDataset") && xml.contains("Source>"), xml);
        LoadedDem loaded = DemReader.load(DemInput.of(vrt), ReadRequest.FULL);
        assertSameValues(jacksboro, loaded.dem(), "gdalbuildvrt's VRT");
        assertSameGeotransform(jacksboro.geometry(), loaded.dem().geometry(), 1e-12, "gdalbuildvrt's VRT");
        run(dir, "gdal_translate", "-q", "-ot", "Float32", "built.vrt", "gdal.tif");
        assertSameValues(DemReader.read(dir.resolve("gdal.tif")), loaded.dem(), "gdal_translate of the VRT");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "resampling | | <DstRect xOff=\"0\" yOff=\"0\" xSize=\"100\" ySize=\"85\"/> | is resampled",
        "scaling | | <ScaleRatio>2</ScaleRatio> | scales values",
        "lookup table | | <LUT>0:0,1000:10</LUT> | has <LUT>",
        "band 2 | | <SourceBand>2</SourceBand> | reads band 2",
        "kernel filter | <KernelFilteredSource><SourceFilename>x.tif</SourceFilename></KernelFilteredSource> | |"
            + " KernelFilteredSource",
        "band scale | <Scale>0.1</Scale> | | <Scale>0.1</Scale>",
        "pixel function | <PixelFunctionType>sum</PixelFunctionType> | | pixel function"})
    void unsupportedFeaturesAreRefusedByName(String what, String band, String source, String expected)
            throws IOException {
        String xml = handWritten(null, band == null ? "" : band, source == null ? "" : source);
        if (what.equals("resampling")) {
            xml = xml.replaceFirst("<DstRect[^>]*/>\\s*", "");
        }
        Path vrt = write(what.replace(' ', '_') + ".vrt", xml);
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.inspect(vrt), what);
        assertTrue(e.getMessage().startsWith(vrt + ": not supported in a VRT: ")
                && e.getMessage().contains(expected), e.getMessage());
    }

    @Test
    void derivedWarpedRotatedAndNestedVrtsAreRefused() throws IOException {
        String base = handWritten(null, "", "");
        assertRefused("derived.vrt", base.replace("band=\"1\">", "band=\"1\" subClass=\"VRTDerivedRasterBand\">"),
                "not supported in a VRT: band 1 is a VRTDerivedRasterBand");
        assertRefused("warped.vrt", base.replace("<VRTDataset ", "<VRTDataset subClass=\"VRTWarpedDataset\" "),
                "not supported in a VRT: a VRTWarpedDataset");
        assertRefused("rotated.vrt", base.replaceFirst(", 0, ", ", 0.0001, "), "rotated or sheared");
        assertRefused("nested.vrt", base.replace("tiles/" + tiles.get(0).getFileName(), "hand.vrt"),
                "is itself a VRT");
        assertRefused("notxml.vrt", "ncols 3\n", "is named .vrt but is not a GDAL VRT");
        assertRefused("other.vrt", "<Other/>", "root element is <Other>, not a GDAL <VRTDataset>");
        assertRefused("broken.vrt", "<VRTDataset rasterXSize=\"3\"", "not well-formed XML");
        assertRefused("nosize.vrt", base.replace("rasterXSize=\"403\"", "rasterXSize=\"0\""),
                "rasterXSize is '0'");
        assertRefused("missing.vrt", base.replace(tiles.get(3).getFileName().toString(), "gone.tif"),
                "gone.tif: no such file");
    }

    @Test
    void aVrtThatReprojectsIsRefused() throws IOException {
        String utm = Files.readString(DEM.resolve("bigtujunga_srtm30m_utm11n.prj"));
        assertRefused("utm.vrt", handWritten(utm, "", ""), "a VRT must not reproject");
    }

    @Test
    void aDoctypeOrExternalEntityIsNotRead() throws IOException {
        Path secret = Files.writeString(tmp.resolve("secret.txt"), "SECRET");
        String xml = "<?xml version=\"1.0\"?>\n<!DOCTYPE VRTDataset [<!ENTITY x SYSTEM \""
                + secret.toUri() + "\">]>\n" + handWritten(null, "", "").replaceFirst("<\\?xml[^>]*>\\s*", "")
                .replace("<SourceBand>1</SourceBand>", "<SourceBand>&x;</SourceBand>");
        Path vrt = write("entity.vrt", xml);
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.inspect(vrt));
        assertTrue(e.getMessage().contains("DOCTYPE"), e.getMessage());
        assertFalse(e.getMessage().contains("SECRET"), e.getMessage());
    }

    private static void assertRefused(String name, String xml, String expected) throws IOException {
        Path vrt = write(name, xml);
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.read(DemInput.of(vrt),
                ReadRequest.FULL), name);
        assertTrue(e.getMessage().contains(expected), name + ": " + e.getMessage());
    }

    static boolean onPath(String tool) {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String dir : path.split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(dir, tool))) {
                return true;
            }
        }
        return false;
    }

    private static void run(Path dir, String... command) throws IOException {
        Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true).start();
        try {
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), String.join(" ", command) + " timed out");
            assertEquals(0, p.exitValue(), String.join(" ", command) + ": " + out);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException(e);
        }
    }
}
