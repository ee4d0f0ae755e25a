package io.github.jdem846.io.geotiff;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.metadata.IIOMetadata;
import org.w3c.dom.NamedNodeMap;
import org.w3c.dom.Node;

/**
 * The fields of a TIFF image file directory, taken from the standard TIFF metadata tree
 * ({@code com_sun_media_imageio_plugins_tiff_image_1.0}) that TwelveMonkeys imageio-tiff exposes: for each tag
 * number, its values as text (numbers or one ASCII string).
 */
final class TiffFields {

    static final String NATIVE_FORMAT = "com_sun_media_imageio_plugins_tiff_image_1.0";

    static final int BITS_PER_SAMPLE = 258;
    static final int COMPRESSION = 259;
    static final int PHOTOMETRIC = 262;
    static final int STRIP_OFFSETS = 273;
    static final int SAMPLES_PER_PIXEL = 277;
    static final int ROWS_PER_STRIP = 278;
    static final int STRIP_BYTE_COUNTS = 279;
    static final int PLANAR_CONFIGURATION = 284;
    static final int PREDICTOR = 317;
    static final int TILE_WIDTH = 322;
    static final int TILE_LENGTH = 323;
    static final int TILE_OFFSETS = 324;
    static final int TILE_BYTE_COUNTS = 325;
    static final int EXTRA_SAMPLES = 338;
    static final int SAMPLE_FORMAT = 339;
    static final int MODEL_PIXEL_SCALE = 33550;
    static final int MODEL_TIEPOINT = 33922;
    static final int MODEL_TRANSFORMATION = 34264;
    static final int GEO_KEY_DIRECTORY = 34735;
    static final int GEO_DOUBLE_PARAMS = 34736;
    static final int GEO_ASCII_PARAMS = 34737;
    static final int GDAL_METADATA = 42112;
    static final int GDAL_NODATA = 42113;

    private final Map<Integer, List<String>> fields;

    private TiffFields(Map<Integer, List<String>> fields) {
        this.fields = fields;
    }

    /** Reads the fields of the first IFD of the metadata tree. */
    static TiffFields of(IIOMetadata metadata) {
        Map<Integer, List<String>> map = new HashMap<>();
        Node root = metadata.getAsTree(NATIVE_FORMAT);
        for (Node ifd = root.getFirstChild(); ifd != null; ifd = ifd.getNextSibling()) {
            if (!"TIFFIFD".equals(ifd.getNodeName())) {
                continue;
            }
            for (Node field = ifd.getFirstChild(); field != null; field = field.getNextSibling()) {
                String number = attribute(field, "number");
                if (number == null) {
                    continue;
                }
                List<String> values = new ArrayList<>();
                for (Node array = field.getFirstChild(); array != null; array = array.getNextSibling()) {
                    for (Node v = array.getFirstChild(); v != null; v = v.getNextSibling()) {
                        String value = attribute(v, "value");
                        if (value != null) {
                            values.add(value);
                        }
                    }
                }
                map.put(Integer.valueOf(number), values);
            }
            break;
        }
        return new TiffFields(map);
    }

    private static String attribute(Node node, String name) {
        NamedNodeMap attributes = node.getAttributes();
        Node a = attributes != null ? attributes.getNamedItem(name) : null;
        return a != null ? a.getNodeValue() : null;
    }

    boolean has(int tag) {
        return fields.containsKey(tag) && !fields.get(tag).isEmpty();
    }

    /**
     * The values as longs; whole numbers beyond the long range (a corrupt BigTIFF LONG8) saturate.
     *
     * @throws IllegalArgumentException naming the tag when a value is not a whole number (a corrupt type: the
     *                                  tags read here are integers)
     */
    long[] longs(int tag) {
        List<String> v = fields.getOrDefault(tag, List.of());
        long[] out = new long[v.size()];
        for (int i = 0; i < out.length; i++) {
            String text = v.get(i).trim();
            try {
                out[i] = Long.parseLong(text);
            } catch (NumberFormatException e) {
                out[i] = wholeNumber(tag, text);
            }
        }
        return out;
    }

    private static long wholeNumber(int tag, String text) {
        try {
            java.math.BigInteger n = new java.math.BigDecimal(text).toBigIntegerExact();
            return n.signum() < 0 ? Long.MIN_VALUE : Long.MAX_VALUE; // beyond the long range
        } catch (NumberFormatException | ArithmeticException e) {
            throw notANumber(tag, text, "a whole number", e);
        }
    }

    /**
     * The failure for a value that is not a number: TwelveMonkeys puts the text of its exception in the tree as
     * the value when the values lie outside the file.
     */
    private static IllegalArgumentException notANumber(int tag, String text, String expected, Exception cause) {
        int at = text.indexOf("Exception: ");
        if (text.startsWith("java.") && at > 0) {
            return new IllegalArgumentException("the values of TIFF tag " + tag + " lie outside the file ("
                    + text.substring(at + "Exception: ".length()) + ")", cause);
        }
        return new IllegalArgumentException("TIFF tag " + tag + " holds '" + text + "', not " + expected, cause);
    }

    /** The first value as an int (saturated at the int range), or {@code dflt} when the tag is absent. */
    int intValue(int tag, int dflt) {
        return has(tag) ? (int) Math.max(Integer.MIN_VALUE, Math.min(Integer.MAX_VALUE, longs(tag)[0])) : dflt;
    }

    /** @throws IllegalArgumentException naming the tag when a value is not a number */
    double[] doubles(int tag) {
        List<String> v = fields.getOrDefault(tag, List.of());
        double[] out = new double[v.size()];
        for (int i = 0; i < out.length; i++) {
            String text = v.get(i).trim();
            try {
                out[i] = Double.parseDouble(text);
            } catch (NumberFormatException e) {
                throw notANumber(tag, text, "a number", e);
            }
        }
        return out;
    }

    /** The ASCII value (several strings joined), or null. */
    String ascii(int tag) {
        List<String> v = fields.get(tag);
        return v == null ? null : String.join("", v);
    }
}
