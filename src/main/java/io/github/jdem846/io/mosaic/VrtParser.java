package io.github.jdem846.io.mosaic;

import io.github.jdem846.internal.SafeXml;
import io.github.jdem846.io.DemFormatException;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/**
 * Parses a GDAL {@code .vrt} mosaic: {@code VRTDataset} with {@code rasterXSize}, {@code rasterYSize},
 * {@code GeoTransform}, {@code SRS} and {@code VRTRasterBand}s whose band 1 has {@code SimpleSource}s and
 * {@code ComplexSource}s ({@code SourceFilename}, {@code SourceBand} 1, {@code SrcRect} and {@code DstRect} of the
 * same size, {@code NODATA}), and {@code NoDataValue}. What would change values otherwise (resampling, scaling,
 * lookup tables, kernel filters, derived or warped bands, other sources) is refused with a message naming it.
 * The XML parser reads no DTD and no external entity.
 */
final class VrtParser {

    /** Largest {@code .vrt} read: a VRT of many thousands of tiles is a few MiB. */
    static final long MAX_BYTES = 64L << 20;

    /** Elements of a source that do not change values. */
    private static final Set<String> HARMLESS_SOURCE = Set.of("SourceFilename", "SourceBand", "SourceProperties",
            "SrcRect", "DstRect", "NODATA", "UseMaskBand", "OpenOptions");

    /** Elements of a band that do not change values. */
    private static final Set<String> HARMLESS_BAND = Set.of("NoDataValue", "ColorInterp", "Description",
            "Metadata", "Histograms", "Overview", "CategoryNames", "ColorTable", "GDALRasterAttributeTable",
            "UnitType", "HideNoDataValue", "MaskBand");

    private VrtParser() {
    }

    static VrtDocument parse(Path vrt) throws IOException {
        Element root = root(vrt);
        if (!root.getAttribute("subClass").isEmpty()) {
            throw unsupported(vrt, "a " + root.getAttribute("subClass") + " (warped or derived dataset)");
        }
        int width = positiveInt(vrt, root, "rasterXSize");
        int height = positiveInt(vrt, root, "rasterYSize");
        double[] geoTransform = null;
        String srs = null;
        List<Element> bands = new ArrayList<>();
        for (Element e : children(root)) {
            switch (e.getTagName()) {
                case "GeoTransform" -> geoTransform = geoTransform(vrt, e.getTextContent());
                case "SRS" -> srs = e.getTextContent().strip();
                case "VRTRasterBand" -> bands.add(e);
                case "GCPList" -> throw unsupported(vrt, "ground control points (GCPList) instead of a"
                        + " GeoTransform");
                default -> {
                    // metadata, overviews, block sizes: no effect on the cells
                }
            }
        }
        if (bands.isEmpty()) {
            throw new DemFormatException(vrt, "has no VRTRasterBand: there is nothing to read");
        }
        Element band = bands.get(0);
        for (Element b : bands) {
            if (b.getAttribute("band").equals("1")) {
                band = b;
            }
        }
        if (!band.getAttribute("subClass").isEmpty()) {
            throw unsupported(vrt, "band 1 is a " + band.getAttribute("subClass")
                    + " (derived, raw or warped band)");
        }
        Double noData = null;
        List<VrtDocument.Source> sources = new ArrayList<>();
        for (Element e : children(band)) {
            String tag = e.getTagName();
            switch (tag) {
                case "NoDataValue" -> noData = number(vrt, tag, e.getTextContent());
                case "SimpleSource", "ComplexSource" -> sources.add(source(vrt, e));
                case "Scale", "Offset" -> {
                    double v = number(vrt, tag, e.getTextContent());
                    if (v != (tag.equals("Scale") ? 1 : 0)) {
                        throw unsupported(vrt, "band 1 has <" + tag + ">" + e.getTextContent().strip() + "</"
                                + tag + "> (unpacked values)");
                    }
                }
                case "PixelFunctionType", "PixelFunctionLanguage", "PixelFunctionCode", "PixelFunctionArguments" ->
                        throw unsupported(vrt, "band 1 has a pixel function (derived band)");
                default -> {
                    if (tag.endsWith("Source")) {
                        throw unsupported(vrt, "band 1 has a " + tag + " (only SimpleSource and ComplexSource are"
                                + " read)");
                    }
                    if (!HARMLESS_BAND.contains(tag)) {
                        throw unsupported(vrt, "band 1 has <" + tag + ">");
                    }
                }
            }
        }
        if (sources.isEmpty()) {
            throw new DemFormatException(vrt, "band 1 has no SimpleSource or ComplexSource: there is nothing to"
                    + " read");
        }
        return new VrtDocument(width, height, geoTransform, srs, noData, bands.size(), sources);
    }

    private static VrtDocument.Source source(Path vrt, Element source) throws DemFormatException {
        String kind = source.getTagName();
        Path file = null;
        int[] src = null;
        int[] dst = null;
        Double noData = null;
        for (Element e : children(source)) {
            String tag = e.getTagName();
            switch (tag) {
                case "SourceFilename" -> file = fileName(vrt, e);
                case "SourceBand" -> {
                    String b = e.getTextContent().strip();
                    if (!b.equals("1")) {
                        throw unsupported(vrt, "a " + kind + " reads band " + b + " of its file (only band 1 of"
                                + " each file is read)");
                    }
                }
                case "SrcRect" -> src = rect(vrt, e);
                case "DstRect" -> dst = rect(vrt, e);
                case "NODATA" -> noData = number(vrt, tag, e.getTextContent());
                case "ScaleOffset", "ScaleRatio" -> {
                    double v = number(vrt, tag, e.getTextContent());
                    if (v != (tag.equals("ScaleRatio") ? 1 : 0)) {
                        throw unsupported(vrt, "a ComplexSource scales values (<" + tag + ">"
                                + e.getTextContent().strip() + "</" + tag + ">)");
                    }
                }
                default -> {
                    if (!HARMLESS_SOURCE.contains(tag)) {
                        throw unsupported(vrt, "a " + kind + " has <" + tag + "> (lookup tables, colour"
                                + " components, exponents and value ranges are not read)");
                    }
                }
            }
        }
        if (file == null) {
            throw new DemFormatException(vrt, "a " + kind + " has no SourceFilename");
        }
        if (src != null && dst != null && (src[2] != dst[2] || src[3] != dst[3])) {
            throw unsupported(vrt, "the source " + file.getFileName() + " is resampled (SrcRect " + src[2] + " × "
                    + src[3] + " cells to DstRect " + dst[2] + " × " + dst[3] + "; only 1:1 placement is read,"
                    + " resample with gdalwarp first)");
        }
        return new VrtDocument.Source(file, src, dst, noData);
    }

    /** {@code SourceFilename}: relative to the VRT's folder when {@code relativeToVRT="1"}. */
    private static Path fileName(Path vrt, Element e) throws DemFormatException {
        String name = e.getTextContent().strip();
        if (name.isEmpty()) {
            throw new DemFormatException(vrt, "a SourceFilename is empty");
        }
        if (name.startsWith("/vsi") || name.contains("://")) {
            throw unsupported(vrt, "the source '" + name + "' is a GDAL virtual file system path or a URL (only"
                    + " local files are read)");
        }
        Path p;
        try {
            p = Path.of(name);
        } catch (InvalidPathException ex) {
            throw new DemFormatException(vrt, "the SourceFilename '" + name + "' is not a valid path: "
                    + ex.getMessage());
        }
        if (name.toLowerCase(Locale.ROOT).endsWith(".vrt")) {
            throw unsupported(vrt, "the source '" + name + "' is itself a VRT (give its files instead)");
        }
        if (e.getAttribute("relativeToVRT").equals("1") && !p.isAbsolute() && vrt.getParent() != null) {
            return vrt.getParent().resolve(p);
        }
        return p;
    }

    /** {xOff, yOff, xSize, ySize} of a SrcRect or DstRect, whole numbers of cells. */
    private static int[] rect(Path vrt, Element e) throws DemFormatException {
        String[] names = {"xOff", "yOff", "xSize", "ySize"};
        int[] r = new int[4];
        for (int i = 0; i < 4; i++) {
            String text = e.getAttribute(names[i]);
            double v = number(vrt, e.getTagName() + " " + names[i], text);
            if (Math.abs(v - Math.rint(v)) > 1e-6 || Math.abs(v) > Integer.MAX_VALUE) {
                throw unsupported(vrt, "a " + e.getTagName() + " has " + names[i] + "=\"" + text + "\" (only whole"
                        + " cells are read: the source is not on the VRT's grid)");
            }
            r[i] = (int) Math.rint(v);
        }
        if (r[2] < 1 || r[3] < 1) {
            throw new DemFormatException(vrt, "a " + e.getTagName() + " is " + r[2] + " × " + r[3]
                    + " cells; its xSize and ySize must be at least 1");
        }
        return r;
    }

    private static double[] geoTransform(Path vrt, String text) throws DemFormatException {
        String[] parts = text.strip().split("\\s*,\\s*");
        if (parts.length != 6) {
            throw new DemFormatException(vrt, "the GeoTransform '" + text.strip() + "' has " + parts.length
                    + " numbers; it needs 6 (origin x, cell width, 0, origin y, 0, −cell height)");
        }
        double[] gt = new double[6];
        for (int i = 0; i < 6; i++) {
            gt[i] = number(vrt, "GeoTransform", parts[i]);
            if (!Double.isFinite(gt[i])) {
                throw new DemFormatException(vrt, "the GeoTransform has " + parts[i] + "; its numbers must be"
                        + " finite");
            }
        }
        if (gt[2] != 0 || gt[4] != 0) {
            throw unsupported(vrt, "the GeoTransform is rotated or sheared (" + parts[2] + ", " + parts[4]
                    + "; only north-up grids are read)");
        }
        if (!(gt[1] > 0) || !(gt[5] < 0)) {
            throw unsupported(vrt, "the GeoTransform has cells of " + parts[1] + " × " + parts[5] + " (only grids"
                    + " with columns going east and rows going south are read)");
        }
        return gt;
    }

    private static double number(Path vrt, String what, String text) throws DemFormatException {
        String t = text.strip();
        try {
            return switch (t.toLowerCase(Locale.ROOT)) {
                case "nan", "-nan" -> Double.NaN;
                case "inf", "+inf", "infinity" -> Double.POSITIVE_INFINITY;
                case "-inf", "-infinity" -> Double.NEGATIVE_INFINITY;
                default -> Double.parseDouble(t);
            };
        } catch (NumberFormatException e) {
            throw new DemFormatException(vrt, what + " '" + t + "' is not a number");
        }
    }

    private static int positiveInt(Path vrt, Element e, String attribute) throws DemFormatException {
        String text = e.getAttribute(attribute);
        try {
            int v = Integer.parseInt(text.strip());
            if (v >= 1) {
                return v;
            }
        } catch (NumberFormatException ex) {
            // below
        }
        throw new DemFormatException(vrt, "VRTDataset's " + attribute + " is '" + text + "'; it must be a whole"
                + " number from 1 to " + Integer.MAX_VALUE);
    }

    static DemFormatException unsupported(Path vrt, String what) {
        return new DemFormatException(vrt, "not supported in a VRT: " + what);
    }

    private static List<Element> children(Element e) {
        List<Element> out = new ArrayList<>();
        NodeList nodes = e.getChildNodes();
        for (int i = 0; i < nodes.getLength(); i++) {
            if (nodes.item(i).getNodeType() == Node.ELEMENT_NODE) {
                out.add((Element) nodes.item(i));
            }
        }
        return out;
    }

    /** The root element, parsed without DTDs or external entities. */
    private static Element root(Path vrt) throws IOException {
        long size = Files.size(vrt);
        if (size > MAX_BYTES) {
            throw new DemFormatException(vrt, "is " + size + " bytes; a VRT of more than " + MAX_BYTES
                    + " bytes is not read");
        }
        byte[] bytes = Files.readAllBytes(vrt);
        Document doc;
        try {
            doc = builder().parse(new ByteArrayInputStream(bytes));
        } catch (SAXParseException e) {
            throw new DemFormatException(vrt, "is not well-formed XML (line " + e.getLineNumber() + ", column "
                    + e.getColumnNumber() + ": " + e.getMessage() + ")", e);
        } catch (SAXException e) {
            throw new DemFormatException(vrt, "is not readable XML: " + e.getMessage(), e);
        }
        Element root = doc.getDocumentElement();
        if (!root.getTagName().equals("VRTDataset")) {
            throw new DemFormatException(vrt, "is XML whose root element is <" + root.getTagName() + ">, not a"
                    + " GDAL <VRTDataset>");
        }
        return root;
    }

    private static DocumentBuilder builder() throws IOException {
        try {
            return SafeXml.newBuilder();
        } catch (ParserConfigurationException e) {
            throw new IOException("the XML parser cannot be configured safely: " + e.getMessage(), e);
        }
    }
}
