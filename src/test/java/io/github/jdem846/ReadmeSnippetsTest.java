package io.github.jdem846;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.testing.TestJvm;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.spi.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code java} blocks of README.md's "As a library" section compile as written, as a library user's module
 * that requires {@code io.github.jdem846} and nothing else: each block's statements become the body of a method,
 * with the imports of that block and of the blocks before it (a reader copies them in order).
 */
class ReadmeSnippetsTest {

    private static final String SECTION = "## As a library";

    @Test
    void theLibrarySectionsJavaBlocksCompileAgainstTheModule(@TempDir Path dir) throws IOException {
        List<String> blocks = javaBlocks(librarySection(Files.readString(Path.of("README.md"))));
        assertTrue(blocks.size() >= 2, "README's library section has its java examples: " + blocks.size());

        Path src = dir.resolve("src");
        Files.createDirectories(src.resolve("readme"));
        Files.writeString(src.resolve("module-info.java"), "module readme { requires io.github.jdem846; }\n");
        List<String> files = new ArrayList<>(List.of(src.resolve("module-info.java").toString()));
        Set<String> imports = new LinkedHashSet<>();
        for (int i = 0; i < blocks.size(); i++) {
            List<String> statements = new ArrayList<>();
            for (String line : blocks.get(i).lines().toList()) {
                if (line.startsWith("import ")) {
                    imports.add(line);
                } else {
                    statements.add("        " + line);
                }
            }
            Path file = src.resolve("readme/Block" + i + ".java");
            Files.writeString(file, "package readme;\n\n" + String.join("\n", imports) + "\n\n"
                    + "final class Block" + i + " {\n    void run() throws Exception {\n"
                    + String.join("\n", statements) + "\n    }\n}\n");
            files.add(file.toString());
        }

        ByteArrayOutputStream messages = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(messages, true, StandardCharsets.UTF_8);
        List<String> args = new ArrayList<>(List.of("-d", dir.resolve("classes").toString(), "-Xlint:all",
                "-Werror", "--module-path", String.join(File.pathSeparator,
                        TestJvm.libraryModulePath(ReliefJob.class))));
        args.addAll(files);
        int status = ToolProvider.findFirst("javac").orElseThrow().run(out, out, args.toArray(String[]::new));
        assertEquals(0, status, messages.toString(StandardCharsets.UTF_8) + "\n" + sources(files));
    }

    @Test
    void blocksAreFoundOnlyInTheirSection() {
        String readme = "# x\n```java\nint a;\n```\n## As a library\ntext\n```java\nint b;\n```\n```sh\nls\n```\n"
                + "### API\n```java\nint c;\n```\n## Next\n```java\nint d;\n```\n";
        assertEquals(List.of("int b;", "int c;"), javaBlocks(librarySection(readme)));
    }

    /** From the section's heading to the next heading of its level. */
    private static String librarySection(String readme) {
        int start = readme.indexOf("\n" + SECTION + "\n");
        assertTrue(start >= 0, "README has a section \"" + SECTION + "\"");
        int end = readme.indexOf("\n## ", start + 1);
        return readme.substring(start, end < 0 ? readme.length() : end);
    }

    /** The contents of the {@code ```java} fenced blocks. */
    private static List<String> javaBlocks(String markdown) {
        List<String> blocks = new ArrayList<>();
        int at = 0;
        while ((at = markdown.indexOf("```java\n", at)) >= 0) {
            int from = at + "```java\n".length();
            int to = markdown.indexOf("\n```", from);
            blocks.add(markdown.substring(from, to));
            at = to + 4;
        }
        return blocks;
    }

    private static String sources(List<String> files) throws IOException {
        StringBuilder all = new StringBuilder();
        for (String f : files) {
            all.append("// ").append(f).append('\n').append(Files.readString(Path.of(f))).append('\n');
        }
        return all.toString();
    }
}
