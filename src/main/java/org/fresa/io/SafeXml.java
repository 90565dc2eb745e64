package org.fresa.io;

import java.io.InputStream;
import java.net.URL;
import java.nio.file.Path;
import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParserFactory;
import javax.xml.transform.sax.SAXSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;

/**
 * The one way Fresa reads XML files (jobs, robots, robot programs): schemas from the class path,
 * and a parser that refuses any DOCTYPE, so that external entities (XXE) and entity expansion
 * cannot happen whatever the file says.
 */
public final class SafeXml {
    private SafeXml() {}

    /** A schema from the class path, e.g. {@code /schemas/job.xsd}. */
    public static Schema schema(String resource) {
        URL url = SafeXml.class.getResource(resource);
        if (url == null) {
            throw new IllegalStateException(resource + " missing from the class path");
        }
        try {
            SchemaFactory f = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
            f.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
            f.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "file,jar:file");
            return f.newSchema(url);
        } catch (SAXException e) {
            throw new IllegalStateException(resource + " is invalid", e);
        }
    }

    /** A namespace-aware source over the stream that refuses DOCTYPEs; file names locate errors. */
    public static SAXSource source(InputStream in, Path file) throws SAXException, ParserConfigurationException {
        SAXParserFactory spf = SAXParserFactory.newInstance();
        spf.setNamespaceAware(true);
        spf.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        spf.setFeature("http://xml.org/sax/features/external-general-entities", false);
        spf.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
        spf.setXIncludeAware(false);
        InputSource src = new InputSource(in);
        src.setSystemId(file.toUri().toString());
        return new SAXSource(spf.newSAXParser().getXMLReader(), src);
    }
}
